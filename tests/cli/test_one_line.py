"""Every `sartco` command says a user's mistake in one line, never a traceback (issue 44): an
unknown model, game, experiment or instance file is exit 2 before anything is played; Ctrl-C is
exit 130; an unknown option gets the command's own usage."""
from __future__ import annotations

import importlib
import subprocess

import pytest

from play_helpers import sartco
from sartco import cli

SMOKE = "games/cobot_instruct/in/instances_smoke.json"


def bad_inputs(tmp):
    """(command line, what the line must say) for each command and each bad input it takes."""
    sample = ["sample", "-n", "1", "-t", "0", "-r", tmp / "s"]
    suite = ["suite", "-r", tmp / "suite", "--erring"]
    return [
        ([*sample, "-m", "nosuch", "-g", "cobot_instruct"], "-m nosuch: no such model"),
        ([*sample, "-m", "mock", "-g", "nosuch"], "-g nosuch: no such game"),
        ([*sample, "-m", "mock", "-g", "cobot_instruct", "-e", "nosuch"], "-e nosuch: "),
        ([*sample, "-m", "mock", "-g", "cobot_instruct", "-i", "nosuch"], "-i nosuch: "),
        (["resume", "-r", tmp, "-g", "cobot_instruct", "-m", "nosuch"], "-m nosuch: no such model"),
        (["resume", "-r", tmp, "-g", "nosuch", "-m", "mock"], "-g nosuch: no such game"),
        ([*suite, "-m", "nosuch", "-g", "cobot_instruct", "-i", "instances_smoke"], "-m nosuch: no such model"),
        ([*suite, "-m", "mock", "-g", "nosuch"], "-g nosuch: not in the plan"),
        ([*suite, "-m", "mock", "-g", "cobot_describe", "-i", "nosuch"], "-i nosuch: "),
        (["check-instances", "-g", "nosuch", SMOKE], "no game 'nosuch'"),
        (["check-instances", "-e", "nosuch", SMOKE], "no experiment 'nosuch'"),
        (["check-instances", tmp / "nosuch.json"], "nosuch.json"),
        (["bench-reward", "--instances", tmp / "nosuch.json"], "no such instance file"),
        (["export-dataset", "--instances", tmp / "nosuch.json", "--out", tmp / "d"], "no such instance file"),
        (["bench-run", "--experiments", "nosuch", "--out", tmp / "b"], "unknown cobot_instruct experiment(s) nosuch"),
        (["generate", "--seed", "-1", "--out", tmp / "v"], "--seed must be 0 or more, not -1"),
    ]


@pytest.mark.parametrize("case", range(16))
def test_each_bad_input_is_one_line_and_exit_2(tmp_path, case):
    argv, says = bad_inputs(tmp_path)[case]
    done = sartco(*argv)
    assert done.returncode == 2, done.stdout + done.stderr
    assert "Traceback" not in done.stdout + done.stderr
    line = done.stderr.strip()
    assert "\n" not in line and line.startswith(f"sartco {argv[0]}: ") and says in line, done.stderr
    assert not (tmp_path / "s").exists() and not (tmp_path / "v").exists()   # nothing played or written


@pytest.mark.parametrize("name", sorted(cli.COMMANDS))
def test_ctrl_c_in_every_command_is_one_line_and_exit_130(monkeypatch, name):
    module, _, suffix = cli.COMMANDS[name][0].partition(":")

    def interrupted(*args, **kwargs):
        raise KeyboardInterrupt

    monkeypatch.setattr(importlib.import_module(module), "configure" + (f"_{suffix}" if suffix else ""), interrupted)
    done = sartco(name)
    assert (done.returncode, done.stderr) == (130, f"sartco {name}: interrupted (Ctrl-C)\n")


def test_an_unknown_option_gets_the_commands_usage_and_help_speaks_to_users():
    done = sartco("suite", "--only-models")
    assert done.returncode == 2
    assert done.stderr.startswith("usage: sartco suite ") and "unrecognized arguments: --only-models" in done.stderr
    top = sartco("--help").stdout
    assert "SARTCo bench:" in top and "sartco doctor" in top and "imported only when chosen" not in top
    assert '{"id": str, "code": str' in sartco("execute", "--help").stdout


def test_the_suites_docstring_shows_commands_it_takes():
    from sartco import suite
    shown = [line.split("#")[0].split() for line in suite.__doc__.splitlines() if line.strip().startswith("sartco suite")]
    assert len(shown) == 2
    for argv in shown:
        parser = cli.argparse.ArgumentParser()
        suite.configure(parser)
        parser.parse_args(argv[2:])   # SystemExit on an option the suite does not take


def test_scores_folders_of_your_own_stay_out_of_git():
    done = subprocess.run(["git", "check-ignore", "scores-mine/table3.md"], cwd=cli.Path(__file__).parents[2],
                          capture_output=True, text=True)
    assert done.returncode == 0, "scores-*/ (the tables of your own runs) must be ignored"
