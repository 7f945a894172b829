"""Instance files are checked for their values, not just their fields, before any model is asked
(sartco.clem.core.instance_checks.check_instances): each bad value is one
line naming the file, the episode and the value, and `clem run` exits 2 without playing. A
generator whose input is missing says so and never replaces an instance file with an empty one."""
import importlib.util
import json
import shutil
import sys
from pathlib import Path

import pytest

from forkserver import command

from sartco.clem.core.errors import InstanceFileError
from sartco.clem.core.instance_checks import EPISODE_FIELDS, check_instances

REPO = Path(__file__).resolve().parents[2]
GAME = REPO / "games" / "cobot_instruct"
CLEM = str(Path(sys.executable).parent / "clem")
SMOKE = json.loads((GAME / "in" / "instances_smoke.json").read_text(encoding="utf-8"))
EXPERIMENT = SMOKE["experiments"][0]   # sb_so_first_order_template; its episode 0 has this target:
assert EXPERIMENT["game_instances"][0]["target"] == {"4:3": [["bridge-v", "green"], ["nut", "red"]],
                                                     "5:3": [["bridge-v", "green"]]}
BRIDGE = ["bridge-v", "green"]

EPISODE_VALUES = {
    # case: (changes to episode 0, what the line says after "game_id 0: ")
    "rows 9": ({"rows": 9}, "field 'rows' is 9, expected 8 (the board every prompt describes)"),
    "rows -1": ({"rows": -1}, "field 'rows' is -1, expected 8 (the board every prompt describes)"),
    "cols 0": ({"cols": 0}, "field 'cols' is 0, expected 8 (the board every prompt describes)"),
    "unknown shape": ({"target": {"4:3": [["gear", "red"]]}},
                      'target cell "4:3": unknown shape "gear" (shapes: washer, nut, screw, bridge-h, bridge-v)'),
    "unknown colour": ({"target": {"4:3": [["nut", "purple"]]}},
                       'target cell "4:3": unknown colour "purple" (colours: red, green, blue, yellow)'),
    "target off the board": ({"target": {"8:3": [["nut", "red"]]}}, 'target cell "8:3": outside the 8x8 board'),
    "negative cell": ({"target": {"-1:3": [["nut", "red"]]}}, 'target cell "-1:3": not a "row:col" key'),
    "not a pair": ({"target": {"4:3": [["nut"]]}}, 'target cell "4:3": ["nut"] is not a [shape, colour] pair'),
    "not a list": ({"target": {"4:3": "nut"}}, 'target cell "4:3": "nut" is not a list of pieces'),
    "empty stack": ({"target": {"4:3": []}}, 'target cell "4:3": a stack of 0 pieces (1 to 4 expected)'),
    "five high": ({"target": {"4:3": [["washer", "red"], ["nut", "red"]] * 2 + [["washer", "red"]]}},
                  'target cell "4:3": a stack of 5 pieces (1 to 4 expected)'),
    "on a screw": ({"target": {"4:3": [["screw", "red"], ["nut", "red"]]}},
                   "target cannot be built through put (not_on_top_of_screw: "),
    "half a bridge": ({"target": {"4:3": [BRIDGE]}},
                      "target cannot be built through put (a bridge listed in one of its two cells only?)"),
    "no turns": ({"turns": []}, "field 'turns' is empty (an episode has at least one turn)"),
    "unknown task": ({"task": "first_ordr"}, 'field \'task\' is "first_ordr", expected one of first_order, '
                                             "sequence_function, optimal_function, repetition"),
}
EXPERIMENT_VALUES = {
    "unknown mode": ({"mode": "corect"}, 'field \'mode\' is "corect", expected one of oneshot, clarify, correct, '
                                         "clarify_correct"),
    "unknown variant": ({"variant": "multi"}, 'field \'variant\' is "multi", expected one of '),
    "unknown board type": ({"board_type": "round"}, 'field \'board_type\' is "round", expected one of simple, regular'),
    "unknown split": ({"split": "dev"}, 'field \'split\' is "dev", expected one of train, val, test'),
}


def write(tmp_path, episode_changes=None, experiment_changes=None) -> Path:
    experiment = json.loads(json.dumps(EXPERIMENT))
    experiment.update(experiment_changes or {})
    experiment["game_instances"][0].update(episode_changes or {})
    path = tmp_path / "instances.json"
    path.write_text(json.dumps({"experiments": [experiment]}))
    return path


def test_the_unchanged_episode_passes(tmp_path):
    assert check_instances(str(write(tmp_path)), EPISODE_FIELDS) == 2


@pytest.mark.parametrize("case", EPISODE_VALUES, ids=EPISODE_VALUES)
def test_bad_episode_value_is_one_line(tmp_path, case):
    changes, expected = EPISODE_VALUES[case]
    path = write(tmp_path, changes)
    with pytest.raises(InstanceFileError) as info:
        check_instances(str(path), EPISODE_FIELDS)
    assert str(info.value).startswith(f"{path}: experiment sb_so_first_order_template, game_id 0: {expected}")
    assert "\n" not in str(info.value)


@pytest.mark.parametrize("case", EXPERIMENT_VALUES, ids=EXPERIMENT_VALUES)
def test_bad_experiment_value_is_one_line(tmp_path, case):
    changes, expected = EXPERIMENT_VALUES[case]
    path = write(tmp_path, experiment_changes=changes)
    with pytest.raises(InstanceFileError) as info:
        check_instances(str(path), EPISODE_FIELDS)
    assert str(info.value).startswith(f"{path}: experiment sb_so_first_order_template: {expected}")


@pytest.mark.slow
def test_clem_run_stops_before_playing(tmp_path):
    """`turns: []` used to raise IndexError mid-run and lose the episode with exit 0."""
    folder = tmp_path / "games" / "cobot_instruct"
    (folder / "in").mkdir(parents=True)
    shutil.copy(GAME / "master.py", folder)
    (folder / "clemgame.json").write_text(json.dumps(json.loads((GAME / "clemgame.json").read_text())[0]))
    shutil.copy(write(tmp_path, {"turns": []}), folder / "in" / "instances.json")
    done = command([CLEM, "run", "-g", "cobot_instruct", "-m", "mock", "-r", "res"], cwd=tmp_path,
                   capture_output=True, text=True, timeout=600)
    assert done.returncode == 2, done.stderr[-1500:]
    [line] = [ln for ln in done.stderr.splitlines() if ln.startswith("clem run -g cobot_instruct: ")]
    assert line.endswith("game_id 0: field 'turns' is empty (an episode has at least one turn)")
    assert "Traceback" not in done.stderr and not list((tmp_path / "res").rglob("interactions.json"))


def copied_generator(tmp_path):
    """cobot_instruct's generator in a game folder of its own, with an instance file it may not lose."""
    folder = tmp_path / "games" / "cobot_instruct"
    (folder / "in").mkdir(parents=True)
    shutil.copy(GAME / "instancegenerator.py", folder)
    (folder / "in" / "instances_paper.json").write_text(KEPT)
    spec = importlib.util.spec_from_file_location("copied_instancegenerator", folder / "instancegenerator.py")
    generator = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(generator)
    return generator, folder / "in" / "instances_paper.json"


KEPT = '{"experiments": ["the file a previous run wrote"]}'
DATASET = ["--dataset", str(REPO / "instances" / "v1")]


def test_paper_generator_refuses_a_missing_shared_folder(tmp_path, monkeypatch, capsys):
    """`instancegenerator.py --protocol paper` with ../shared missing exited 0 and replaced the
    1,950-episode file with {"experiments": []}: now exit 2, a line naming the path, no write."""
    import sartco.paper.episodes as paper_episodes

    missing = tmp_path / "shared" / "sartco-data" / "published"
    monkeypatch.setattr(paper_episodes, "DEFAULT_PUBLISHED", missing)
    generator, kept = copied_generator(tmp_path)
    assert generator.main(["--protocol", "paper", *DATASET]) == 2
    assert capsys.readouterr().err == f"instancegenerator: {missing}: no such file or folder; no instance file written\n"
    assert kept.read_text() == KEPT


def test_paper_generator_without_a_data_folder_names_the_setting(tmp_path, monkeypatch, capsys):
    """A wheel install without $SARTCO_DATA (issue 33): the line says which setting to give, not a
    placeholder path; with $SARTCO_DATA naming a missing folder it names that folder and the setting."""
    import os
    import sys

    import sartco.paper.episodes as paper_episodes
    from sartco import settings

    monkeypatch.setattr(settings, "DATA", None)
    monkeypatch.setattr(paper_episodes, "DEFAULT_PUBLISHED", settings.data_path("published"))
    generator, kept = copied_generator(tmp_path)
    assert generator.main(["--protocol", "paper", *DATASET]) == 2
    assert capsys.readouterr().err == (
        "instancegenerator: no SARTCo data folder: set $SARTCO_DATA or `sartco --data DIR` (the folder with "
        "published/, gold_boards/, paper-protocol/); no instance file written\n")
    assert kept.read_text() == KEPT
    done = command([sys.executable, str(generator.__file__), "--protocol", "paper", *DATASET], cwd=REPO,
                   capture_output=True, text=True, timeout=300,
                   env={**os.environ, "SARTCO_DATA": str(tmp_path / "no-data")})
    assert done.returncode == 2 and done.stderr == (
        f"instancegenerator: SARTCo data folder {tmp_path / 'no-data'} not found: set $SARTCO_DATA or `sartco --data "
        "DIR` (the folder with published/, gold_boards/, paper-protocol/); no instance file written\n")
    assert kept.read_text() == KEPT


def test_paper_generator_refuses_a_folder_without_episodes(tmp_path, capsys):
    empty = tmp_path / "published"
    empty.mkdir()
    generator, kept = copied_generator(tmp_path)
    assert generator.main(["--protocol", "paper", "--paper-data", str(empty), *DATASET]) == 2
    assert capsys.readouterr().err == \
        f"instancegenerator: {empty}: no episodes were generated from it; no instance file written\n"
    assert kept.read_text() == KEPT
