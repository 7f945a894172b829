"""sartco.clem.tooling.evaluate writes the files of `clem eval -g GAME -m MODEL` run for each pair
in turn (what make main did), byte for byte: compared with clemcore's own perform_evaluation on
results folders of several games and models, and its episode frame with clemeval's row-by-row one
on any mix of score values."""
from __future__ import annotations

import json
import random
import shutil
from pathlib import Path

import pandas as pd
from clemcore import clemeval
from hypothesis import given, settings
from hypothesis import strategies as st

from sartco.clem.tooling import evaluate

TABLES = ("raw.csv", "results.csv", "results.html")
VALUES = st.one_of(st.integers(-5, 5), st.floats(allow_nan=True, allow_infinity=False, width=32), st.booleans(),
                   st.none(), st.sampled_from(["success", "given", "mismatch_location", "1", "a,b"]))


def _scores(values: list) -> dict:
    """A load_scores dict of two episodes sharing the values (one metric per value)."""
    half = max(1, len(values) // 2)
    return {("g", "m", "e", "instance_0"): {"episodes": {f"metric {i}": v for i, v in enumerate(values[:half])}},
            ("g", "m", "e", "instance_1"): {"episodes": {f"metric {i}": v for i, v in enumerate(values[half:])}}}


@settings(max_examples=150, deadline=None)
@given(st.lists(VALUES, max_size=12))
def test_the_episode_frame_is_clemevals_row_by_row_frame(values):
    scores = _scores(values)
    expected = clemeval.build_df_episode_scores(scores)
    got = evaluate.episode_frame(scores)
    assert list(got.dtypes) == list(expected.dtypes)
    assert got.to_csv() == expected.to_csv()


def _results(root: Path, seed: int) -> list[tuple[str, str]]:
    """A results folder as clemcore lays it out: score files of 3 games x 3 models, values of the
    kinds SARTCo's scorers log (numbers, NaN, categories, lists); the pairs in the order played."""
    rng = random.Random(seed)
    pairs = []
    for model in ("mock", "rulebased", "erring"):
        for game in ("cobot_instruct", "cobot_describe", "cobot_instruct_feedback"):
            pairs.append((game, model))
            for exp in ("sb_so_first_order_template", "rb_co_repetition_template"):
                for n in range(rng.randint(1, 6)):
                    folder = root / model / game / exp / f"instance_{n:05d}"
                    folder.mkdir(parents=True)
                    episode = {"Aborted": rng.choice([0, 1]), "Success": rng.choice([0, 1]), "Lose": 0,
                               "Main Score": rng.choice([100, 0, 57.14, None]), "Executability": rng.random(),
                               "Category": rng.choice(["success", "mismatch_location", "syntax_error"]),
                               "Probe Function": rng.choice(["given", "model", None]), "Turns": [1, 2][: rng.randint(0, 2)]}
                    (folder / "scores.json").write_text(json.dumps({"turn scores": {}, "episode scores": episode}))
    rng.shuffle(pairs)
    return pairs


def test_the_files_equal_clem_evals_one_pair_at_a_time(tmp_path, capsys):
    for seed in range(3):
        ours, theirs = tmp_path / f"ours{seed}", tmp_path / f"theirs{seed}"
        pairs = _results(ours, seed)
        shutil.copytree(ours, theirs)
        for game, model in pairs:  # `clem eval -r theirs -g game -m model`, after make main's rm raw.csv
            clemeval.perform_evaluation(str(theirs), game_selector=game, model_selector=model)
        evaluate.evaluate(ours, pairs)
        for name in TABLES:
            assert (ours / name).read_bytes() == (theirs / name).read_bytes(), (seed, name)
        assert len(pd.read_csv(ours / "raw.csv")) > 0


def test_a_results_folder_without_the_pairs_is_refused(tmp_path):
    try:
        evaluate.evaluate(tmp_path, [])
    except ValueError as exc:
        assert "no game/model pairs" in str(exc)
    else:
        raise AssertionError("no pairs: no tables")
