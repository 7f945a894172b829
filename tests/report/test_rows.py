"""The report's row (sartco.report.rows): typed, built in one place, with the model the episode
itself records (interactions.json meta.results_folder, as clemcore writes it), not the name of
the folder it was copied into."""
import json
import shutil
import typing

from sartco.report.rows import EpisodeRow
from sartco.report.rows import collect

from report_helpers import write_results


def record_model(results, folder: str, model: str) -> None:
    for episode in (results / folder).rglob("instance_*"):
        (episode / "interactions.json").write_text(json.dumps({"meta": {"results_folder": model}}))


def test_a_row_names_the_model_its_episode_records(tmp_path):
    results = tmp_path / "results"
    write_results(results, "gpt-4o-t0.0", [1, 0])
    record_model(results, "gpt-4o-t0.0", "gpt-4o-t0.0")
    shutil.move(results / "gpt-4o-t0.0", results / "copied")   # a results folder renamed by hand
    write_results(results, "mock", [1])                       # played before: no interactions.json
    rows = collect(results)
    assert sorted((r["model"], r["episode"], r["es"]) for r in rows) == [
        ("gpt-4o-t0.0", "instance_00000", 1.0), ("gpt-4o-t0.0", "instance_00001", 0.0), ("mock", "instance_00000", 1.0)]
    (results / "mock" / "cobot_instruct" / "sb_so_first_order_template" / "instance_00000" / "interactions.json"
     ).write_text("{not json")                                # unreadable: the folder name again
    assert sorted(r["model"] for r in collect(results)) == ["gpt-4o-t0.0", "gpt-4o-t0.0", "mock"]


def test_every_row_holds_exactly_the_fields_of_its_type(tmp_path):
    write_results(tmp_path, "mock", [1, 0])
    required = set(typing.get_type_hints(EpisodeRow)) - EpisodeRow.__optional_keys__
    assert all(set(row) == required for row in collect(tmp_path))
