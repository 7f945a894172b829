"""Bad instance files stop `clem run` before any model is asked, with one line naming the file,
the experiment and the field, and exit code 2 (sartco.clem.core.benchmark); clemcore alone would log a
traceback and go on, or play "0 rows" of an unknown experiment and exit 0."""
import json
import shutil
import sys
from pathlib import Path

import pytest

from forkserver import command

from sartco.clem.core.benchmark import RunOptions, clem_run_options, resume_selector, run_options
from sartco.clem.core.errors import InstanceFileError
from sartco.clem.core.instance_checks import EPISODE_FIELDS, check_instances

REPO = Path(__file__).resolve().parents[2]
GAME = REPO / "games" / "cobot_instruct"
CLEM = str(Path(sys.executable).parent / "clem")
SMOKE = json.loads((GAME / "in" / "instances_smoke.json").read_text(encoding="utf-8"))


def without_target(data):
    data = json.loads(json.dumps(data))
    del data["experiments"][1]["game_instances"][1]["target"]
    return json.dumps(data)


BAD = {
    # name: (instance file text or None for no file, clem run options, what the one line says)
    "missing target": (without_target(SMOKE), [],
                       "experiment sb_so_sequence_function_template, game_id 1: missing field 'target'"),
    "truncated file": (json.dumps(SMOKE)[:5000], [], "instances.json: not valid JSON, truncated or broken at line 1 column"),
    "missing -i file": (None, ["-i", "instances_typo"], "instances_typo.json: no such instance file (files in"),
    "unknown experiment": (json.dumps(SMOKE), ["-e", "sb_so_first_order"],
                           "no experiment 'sb_so_first_order' (experiments: sb_so_first_order_template, "
                           "sb_so_sequence_function_template, sb_so_optimal_function_template, "
                           "rb_so_repetition_template, rb_co_repetition_template)"),
}


@pytest.fixture
def game_copy(tmp_path):
    """The game's master and its first clemgame.json entry in a folder of its own, so the bad
    files go into a copy of in/ (clemcore reads instance files from the game folder only)."""
    folder = tmp_path / "games" / "cobot_instruct"
    (folder / "in").mkdir(parents=True)
    shutil.copy(GAME / "master.py", folder)
    entry = json.loads((GAME / "clemgame.json").read_text())[0]
    (folder / "clemgame.json").write_text(json.dumps(entry))
    return tmp_path


@pytest.mark.slow
@pytest.mark.parametrize("case", BAD, ids=BAD)
def test_bad_input_stops_clem_run_with_one_line(game_copy, case):
    text, options, expected = BAD[case]
    if text is not None:
        (game_copy / "games" / "cobot_instruct" / "in" / "instances.json").write_text(text)
    done = command([CLEM, "run", "-g", "cobot_instruct", "-m", "mock", "-r", "res", *options],
                   cwd=game_copy, capture_output=True, text=True, timeout=600)
    assert done.returncode == 2, done.stdout[-1500:] + done.stderr[-1500:]
    [line] = [ln for ln in done.stderr.splitlines() if ln.startswith("clem run -g cobot_instruct: ")]
    assert expected in line and "/games/cobot_instruct/in/instances" in line
    assert "Traceback" not in done.stderr + done.stdout
    assert not list((game_copy / "res").rglob("interactions.json"))  # no episode was played


@pytest.mark.slow
def test_good_file_plays(game_copy):
    (game_copy / "games" / "cobot_instruct" / "in" / "instances.json").write_text(json.dumps(SMOKE))
    done = command([CLEM, "run", "-g", "cobot_instruct", "-m", "mock", "-r", "res", "-e",
                    "rb_co_repetition_template"], cwd=game_copy, capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stderr[-1500:]
    assert len(list((game_copy / "res").rglob("interactions.json"))) == 2


def benchmark_of(game: str):
    import importlib.util
    import inspect

    from clemcore.clemgame.benchmark import is_game_benchmark

    spec = importlib.util.spec_from_file_location(f"{game}_master", REPO / "games" / game / "master.py")
    master = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(master)
    [(_, benchmark)] = inspect.getmembers(master, is_game_benchmark)  # the one class clemcore plays
    return benchmark


@pytest.mark.parametrize("game, committed", [
    ("cobot_instruct", {"instances": 650, "instances_ablations": 850, "instances_feedback": 650, "instances_smoke": 10}),
    ("cobot_describe", {"instances": 390, "instances_smoke": 6, "instances_slice": 6, "instances_dialogue": 1170,
                        "instances_dialogue_slice": 18}),
])
def test_every_instance_file_passes(game, committed):
    """The committed files and any generated beside them (published, paper protocol, train) pass
    the check `clem run` makes: every field of the game's episode type (sartco.episode)."""
    benchmark = benchmark_of(game)
    assert set(EPISODE_FIELDS) < set(benchmark.episode_fields)
    counts = {p.stem: check_instances(str(p), benchmark.fields_of)
              for p in sorted((REPO / "games" / game / "in").glob("instances*.json"))}
    assert {name: counts[name] for name in committed} == committed


@pytest.mark.parametrize("episode, message", [
    ({"game_id": 3, "target": [], "rows": 8}, "game_id 3: field 'target' is list [], expected an object"),
    ({"game_id": 4, "target": {}, "rows": True}, "game_id 4: field 'rows' is bool true, expected a number"),
    ("nope", "episode 0: not an object"),
])
def test_field_types(tmp_path, episode, message):
    path = tmp_path / "instances.json"
    path.write_text(json.dumps({"experiments": [{"name": "e", "game_instances": [episode]}]}))
    with pytest.raises(InstanceFileError) as info:
        check_instances(str(path), {"target": dict, "rows": int})
    assert str(info.value) == f"{path}: experiment e, {message}"


@pytest.mark.parametrize("data", [[], {"experiments": []}, {"experiments": [{"game_instances": []}]}])
def test_no_experiments(tmp_path, data):
    path = tmp_path / "instances.json"
    path.write_text(json.dumps(data))
    with pytest.raises(InstanceFileError, match="experiment"):
        check_instances(str(path), {})


@pytest.mark.parametrize("argv, expected", [
    (["/venv/bin/clem", "run", "-g", "x", "-m", "mock", "-e", "abc"], (True, "abc")),
    (["clem", "run", "-g", "x", "-m", "a", "b", "--experiment_name=abc"], (True, "abc")),
    (["clem", "run", "-g", "x", "-m", "mock"], (True, None)),
    (["clem", "score", "-g", "x"], (False, None)),
    (["/usr/bin/pytest", "-e", "abc"], (False, None)),
    ([], (False, None)),
])
def test_clem_run_options(argv, expected):
    run = clem_run_options(argv)
    assert (run is not None, run and run.experiment) == expected


def test_resume_options_travel_in_the_game_spec(monkeypatch):
    """`sartco resume` hands clemcore's `run` a selector with its options; clemcore unifies it with
    the registered entry, and the benchmark built from that spec reads them there (no global)."""
    from clemcore.clemgame import GameRegistry

    monkeypatch.chdir(REPO)
    registry = GameRegistry.from_directories_and_cwd_files()
    episodes = [["sb_so_first_order_template", 0], ["rb_so_repetition_template", 5]]
    selector = resume_selector("cobot_instruct", Path("res"), episodes, 2)
    [spec] = registry.get_game_specs_that_unify_with(selector, verbose=False)
    assert spec.game_path == str(GAME)
    assert run_options(spec, ["pytest"]) == RunOptions(Path("res"), None, 2, episodes)
    plain = registry.get_game_specs_that_unify_with("cobot_instruct", verbose=False)[0]
    assert run_options(plain, ["pytest"]) is None
    assert run_options(plain, ["clem", "run", "-g", "x", "-e", "abc", "-r", "out"]) == RunOptions(Path("out"), "abc")
    assert run_options(plain, ["clem", "run", "-g", "x", "-r", "out", "-b", "4"]) == RunOptions(Path("out"), None, 4)
