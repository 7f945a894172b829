"""`sartco instances` and the two game scripts: one command, one error style (one line, exit 2,
no file written), the scripts' old flags read into its modes, the scripts thin wrappers of it.
(scripts/instance_bytes.sh compares every kind of file with the files the generators wrote
before they were one command.)"""
from __future__ import annotations

import ast
import importlib.util
import json
from importlib import metadata
import shutil
from argparse import Namespace
from pathlib import Path

import pytest

from forkserver import command

from sartco.cli import main as sartco_main
from sartco.dataset import REGULAR_COMPLEX, REGULAR_SIMPLE, SIMPLE, board_kind, experiment_name, kind_named
from sartco.instancegen.command import MODES, generate
from sartco.instancegen.legacy import parse
from sartco.instancegen.options import DEFAULTS

REPO = Path(__file__).resolve().parents[2]
GAMES = ("cobot_instruct", "cobot_describe")


def copied_script(tmp_path, game):
    """games/<game>/instancegenerator.py in a game folder of its own (it writes into that folder's in/)."""
    folder = tmp_path / "games" / game
    folder.mkdir(parents=True)
    shutil.copy(REPO / "games" / game / "instancegenerator.py", folder)
    spec = importlib.util.spec_from_file_location(f"copied_{game}", folder / "instancegenerator.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module, folder


@pytest.mark.parametrize("argv, message", [
    (["describe", "--seed", "-1"], "--seed must be between 0 and 4294967295, not -1"),
    (["instruct", "--seed", str(2**32)], "--seed must be between 0 and 4294967295, not 4294967296"),
    (["instruct-fresh", "-3"], "the fresh seed must be between 0 and 4294967295, not -3"),
    (["instruct", "--examples", "11"], "--examples must be between 0 and 10, not 11"),
    (["instruct", "--attempts", "1"], "--attempts must be at least 2, not 1"),
    (["instruct", "--smoke", "0"], "--smoke must be at least 1, not 0"),
    (["describe", "--slice", "0"], "--slice must be at least 1, not 0"),
    (["instruct-train", "--train-episodes", "-1"], "--train-episodes must be at least 0, not -1"),
    (["describe", "--dataset", "{tmp}/missing"], "{tmp}/missing/manifest.json: no dataset manifest"),
    (["instruct-published", "--published", "{tmp}/nothing"], "{tmp}/nothing/manifest.json: no dataset manifest"),
    (["instruct-describers", "{tmp}/gone"], "{tmp}/gone/manifest.json: no dataset manifest"),
])
def test_a_bad_value_is_one_line_and_exit_2(argv, message, tmp_path, capsys):
    argv = [a.replace("{tmp}", str(tmp_path)) for a in argv]
    before = {p: p.stat().st_mtime_ns for game in GAMES for p in (REPO / "games" / game / "in").iterdir()}
    assert sartco_main(["instances", *argv]) == 2
    err = capsys.readouterr().err
    assert err.startswith(f"sartco instances: {message.replace('{tmp}', str(tmp_path))}") and err.count("\n") == 1
    assert before == {p: p.stat().st_mtime_ns for p in before}  # no instance file touched


@pytest.mark.parametrize("argv, wrong", [
    (["describe", "--seed", "abc"], "argument --seed: invalid int value: 'abc'"),
    (["sideways"], "argument MODE: invalid choice: 'sideways'"),
    (["describe", "--fresh-episodes", "3"], "unrecognized arguments: --fresh-episodes 3"),
])
def test_what_argparse_rejects_also_exits_2(argv, wrong, capsys):
    with pytest.raises(SystemExit) as exit_:
        sartco_main(["instances", *argv])
    assert exit_.value.code == 2 and wrong in capsys.readouterr().err


def test_a_game_script_says_the_same_line_and_writes_nothing(tmp_path, capsys):
    script, folder = copied_script(tmp_path, "cobot_describe")
    assert script.main(["--dataset", str(tmp_path / "missing"), "--slice", "2"]) == 2
    assert capsys.readouterr().err == (f"instancegenerator: {tmp_path / 'missing' / 'manifest.json'}: no dataset "
                                       "manifest (expected a folder written by `sartco generate` or `sartco import`)\n")
    script, folder = copied_script(tmp_path, "cobot_instruct")
    assert script.main(["--train", "--published", "instances/published"]) == 2
    assert capsys.readouterr().err == ("instancegenerator: --train and --published write different files: give one "
                                       "of them (--published goes alone or with --fresh)\n")
    assert script.main(["--attempts", "1"]) == 2
    assert capsys.readouterr().err == "instancegenerator: --attempts must be at least 2, not 1\n"
    assert not list(tmp_path.rglob("*.json"))


@pytest.mark.parametrize("game, argv, mode, options", [
    ("cobot_instruct", [], "instruct", {}),
    ("cobot_instruct", ["--seed", "7", "--smoke", "1"], "instruct", {"seed": 7, "smoke": 1}),
    ("cobot_instruct", ["--published", "P"], "instruct-published", {"published": Path("P")}),
    ("cobot_instruct", ["--protocol", "paper", "--paper-data", "D"], "instruct-paper", {"paper_data": Path("D")}),
    ("cobot_instruct", ["--fresh", "7"], "instruct-fresh", {"fresh": 7, "published": None}),
    ("cobot_instruct", ["--fresh", "7", "--published", "P"], "instruct-fresh", {"fresh": 7, "published": Path("P")}),
    ("cobot_instruct", ["--train", "--train-episodes", "3"], "instruct-train", {"train_episodes": 3}),
    ("cobot_instruct", ["--describers", "X"], "instruct-describers", {"describers": Path("X")}),
    ("cobot_describe", ["--slice", "2", "--questions", "1"], "describe", {"slice": 2, "questions": 1}),
])
def test_the_scripts_flags_choose_a_mode_of_the_command(game, argv, mode, options):
    chosen, namespace = parse(game, argv)
    assert chosen == mode and MODES[mode][0] == game
    assert {**DEFAULTS, **options}.items() <= vars(namespace).items()


@pytest.mark.parametrize("game", GAMES)
def test_both_game_scripts_are_thin_wrappers_of_the_one_command(game):
    """No logic in the game folders: a docstring, imports, and main() handing its argv to script_main."""
    source = (REPO / "games" / game / "instancegenerator.py").read_text()
    tree = ast.parse(source)
    functions = [n for n in tree.body if isinstance(n, (ast.FunctionDef, ast.ClassDef))]
    assert [f.name for f in functions] == ["main"] and len(functions[0].body) == 1
    call = functions[0].body[0].value
    assert isinstance(call, ast.Call) and call.func.id == "script_main" and call.args[0].value == game
    imported = {n.module for n in ast.walk(tree) if isinstance(n, ast.ImportFrom)}
    assert imported == {"pathlib", "sartco.instancegen.command"}
    assert len(source.splitlines()) < 30


def test_the_script_and_the_command_write_the_same_bytes(tmp_path, capsys):
    """The train file through the game script's flags and through `sartco instances instruct-train`."""
    script, folder = copied_script(tmp_path, "cobot_instruct")
    assert script.main(["--train", "--train-episodes", "1", "--seed", "3"]) == 0
    [path] = generate("instruct-train", Namespace(**{**DEFAULTS, "train_episodes": 1, "seed": 3}),
                      game_dir=tmp_path / "command")
    written = folder / "in" / "instances_train.json"
    assert Path(path).read_bytes() == written.read_bytes()
    data = json.loads(written.read_text())
    assert data["dataset"]["generator_seed"] == 3 and len(data["experiments"]) == 5
    assert [i["game_id"] for e in data["experiments"] for i in e["game_instances"]] == [0] * 5  # per experiment
    assert f"{written}: 5 experiments, 5 episodes" in capsys.readouterr().out


@pytest.mark.parametrize("spoil, message", [
    ("config", "{tmp}/v1/manifest.json: no 'config'"),
    ("train", "{tmp}/v1/simple_simple_train.json: missing (the in-context examples come from its train split)"),
])
def test_a_fresh_run_on_a_dataset_without_config_or_train_split_says_which_and_exits_2(spoil, message, tmp_path,
                                                                                          capsys):
    """The fresh boards follow the seed-42 dataset's config and draw their examples from its train split:
    a dataset lacking either is named in one line, not a traceback."""
    dataset = tmp_path / "v1"
    shutil.copytree(REPO / "instances" / "v1", dataset)
    manifest = json.loads((dataset / "manifest.json").read_text())
    if spoil == "config":
        del manifest["config"]
    else:
        del manifest["files"]["simple_simple_train.json"]
    (dataset / "manifest.json").write_text(json.dumps(manifest))
    before = {p: p.stat().st_mtime_ns for p in (REPO / "games" / "cobot_instruct" / "in").iterdir()}
    assert sartco_main(["instances", "instruct-fresh", "7", "--dataset", str(dataset)]) == 2
    err = capsys.readouterr().err
    assert err.startswith(f"sartco instances: {message.replace('{tmp}', str(tmp_path))}") and err.count("\n") == 1
    assert before == {p: p.stat().st_mtime_ns for p in before}


COMMITTED = [("cobot_instruct", name) for name in ("instances", "instances_ablations", "instances_feedback",
                                                   "instances_smoke")] + \
            [("cobot_describe", name) for name in ("instances", "instances_smoke", "instances_slice", "instances_dialogue",
                                                   "instances_dialogue_slice")]


@pytest.mark.parametrize("game, name", COMMITTED)
def test_every_committed_file_keeps_the_one_convention(game, name):
    """Both games: an experiment is named by sartco.dataset.experiment_name from its own fields
    (<cell>_<task>_<source>, then _<variant> when it has one) and counts game_id from 0."""
    experiments = json.loads((REPO / "games" / game / "in" / f"{name}.json").read_text())["experiments"]
    for e in experiments:
        kind = board_kind(e["board_type"], e["object_type"])
        variant = e.get("mode") or (e.get("ablation") and "{kind}_{value}".format(**e["ablation"]))
        feedback = "feedback" if e.get("feedback_of") else None
        assert e["name"] == experiment_name(kind, e["task"], e["source"], variant, feedback)
        assert e.get("feedback_of") in (None, experiment_name(kind, e["task"], e["source"], variant))
        assert [i["game_id"] for i in e["game_instances"]] == list(range(len(e["game_instances"])))


@pytest.mark.parametrize("game, name", COMMITTED)
def test_every_committed_file_says_which_release_wrote_it(game, name):
    """Issue 33: an instance file records its generator (the release, not the commit: the same seed
    and config give the same bytes on every commit of a release); run.json copies it."""
    data = json.loads((REPO / "games" / game / "in" / f"{name}.json").read_text())
    assert data["generator"] == {"package": "sartco-bench", "version": metadata.version("sartco-bench")}


def test_the_naming_rule():
    assert experiment_name(SIMPLE, "first_order", "template") == "sb_so_first_order_template"
    assert experiment_name(REGULAR_COMPLEX, "repetition", "describer", "clarify_correct") == \
        "rb_co_repetition_describer_clarify_correct"
    assert experiment_name(REGULAR_SIMPLE, "repetition", "org/model", None, "feedback") == \
        "rb_so_repetition_org_model_feedback"
    with pytest.raises(ValueError):
        kind_named("simple_boards")  # one vocabulary of kinds: key, prefix, cell


def test_a_partial_describer_dataset_names_the_experiments_to_play(tmp_path):
    """A describer run of one of cobot_describe's three experiments, imported: the builder file
    cannot be made, and the line says which experiments to play and how (issue 33)."""
    import sys

    from play_helpers import clem

    results = tmp_path / "results"
    clem("run", "-g", "cobot_describe", "-m", "mock", "-i", "instances_slice", "-e", "sb_so_optimal_function_describer",
         "-r", str(results))
    assert sartco_main(["import-instructions", "-r", str(results), "--out", str(tmp_path / "described")]) == 0
    script, folder = copied_script(tmp_path, "cobot_instruct")
    done = command([sys.executable, str(folder / "instancegenerator.py"), "--describers", str(tmp_path / "described")],
                   cwd=REPO, capture_output=True, text=True, timeout=300)
    assert done.returncode == 2 and done.stderr == (
        f"instancegenerator: {tmp_path / 'described'}: the describer run played no episode of rb_so_repetition_describer, "
        "rb_co_repetition_describer: play each with `clem run -g cobot_describe -e EXPERIMENT -m MODEL -r RESULTS` into "
        f"the describer's results, then `sartco import-instructions -r RESULTS --out {tmp_path / 'described'}` again\n")
    assert not (folder / "in").exists()
