"""The tests' command processes (tests/helpers/forkserver.py): a command forked from the warm server
says, writes and exits as the same command in a fresh interpreter does."""
import os
import re
import subprocess
import sys
from pathlib import Path

import forkserver
from forkserver import command

REPO = Path(__file__).resolve().parents[2]
BIN = Path(sys.executable).parent
SCRIPT = """import os, sys
print(sys.argv, os.getcwd() == os.environ["EXPECTED_CWD"], os.environ.get("ONLY_HERE"), sys.stdin.read().upper())
print("to stderr", file=sys.stderr)
print(__name__, sys.path[0] == os.path.dirname(os.path.abspath(__file__)), "clemcore" in sys.modules)
if sys.argv[1:] == ["raise"]:
    raise ValueError("the script's own error")
sys.exit(sys.argv[1] if sys.argv[1:] else 0)
"""


def untimed(text: str) -> str:
    """clemcore's log lines without their time stamps and durations."""
    return re.sub(r"\d{4}-\d\d-\d\d \d\d:\d\d:\d\d,\d+|\d+:\d\d:\d\d\.\d+", "<time>", text)


def both(args, **kwargs) -> tuple[subprocess.CompletedProcess, subprocess.CompletedProcess]:
    fresh = subprocess.run([str(a) for a in args], capture_output=True, text=True, timeout=300,
                           stdin=None if "input" in kwargs else subprocess.DEVNULL, **kwargs)
    return fresh, command(args, timeout=300, **kwargs)


def test_a_forked_command_says_and_exits_as_a_fresh_one(tmp_path):
    script = tmp_path / "probe.py"
    script.write_text(SCRIPT)
    env = dict(os.environ, EXPECTED_CWD=str(tmp_path), ONLY_HERE="yes")
    for args in (["raise"], ["a message"], ["3"], []):
        fresh, forked = both([sys.executable, script, *args], cwd=tmp_path, env=env, input="some input")
        assert forked.returncode == fresh.returncode and forked.stdout == fresh.stdout, (args, forked, fresh)
        if args == ["raise"]:  # the traceback's frames differ (runpy's); its end does not
            assert fresh.returncode == 1 and forked.stderr.splitlines()[-1] == fresh.stderr.splitlines()[-1]
        else:
            assert forked.stderr == fresh.stderr
        if args == ["a message"]:  # sys.exit("...") prints it and exits 1, as the interpreter does
            assert fresh.returncode == 1 and fresh.stderr.endswith("a message\n")


def test_a_clem_run_says_exits_and_logs_as_a_fresh_one(tmp_path):
    """clemcore and sartco are imported in the child: clemcore's logging config writes clembench.log
    in the command's own folder, and sartco's check of the instance file stops the run (exit 2)."""
    (tmp_path / "a").mkdir()
    (tmp_path / "b").mkdir()
    args = [BIN / "clem", "run", "-g", "cobot_instruct", "-m", "mock", "-i", "no_such_file"]
    env = dict(os.environ, CLEMBENCH_HOME=str(REPO))  # the checkout's games, from any folder
    fresh = subprocess.run([str(a) for a in args], cwd=tmp_path / "a", env=env, capture_output=True, text=True,
                           timeout=300)
    forked = command(args, cwd=tmp_path / "b", env=env, timeout=300)
    assert forked.returncode == fresh.returncode == 2 and "no_such_file" in fresh.stderr
    assert untimed(forked.stdout) == untimed(fresh.stdout) and untimed(forked.stderr) == untimed(fresh.stderr)
    assert (tmp_path / "a" / "clembench.log").is_file() and (tmp_path / "b" / "clembench.log").is_file()
    server, _ = forkserver._start()
    assert server.poll() is None  # the server checked at its start that clemcore and sartco are not imported


def test_what_runs_forked_and_what_fresh(tmp_path):
    env = dict(os.environ, PATH=f"{BIN}{os.pathsep}{os.environ['PATH']}")
    module = [sys.executable, "-m", "sartco", "export-prompts", "--protocol", "paper"]
    assert forkserver._python_args(module, env) == (sys.executable, module[1:])
    assert forkserver._python_args(["clem", "run"], env) == (sys.executable, [str(BIN / "clem"), "run"])  # on PATH
    assert forkserver._python_args([sys.executable, "-c", "pass"], env) is None  # -c: always fresh
    assert forkserver._python_args(["bash", "-c", "true"], env) is None
    seeded = command([sys.executable, "-c", "print(hash('sartco'))"], env=dict(env, PYTHONHASHSEED="123"))
    assert seeded.stdout == command([sys.executable, "-c", "print(hash('sartco'))"],
                                    env=dict(env, PYTHONHASHSEED="123")).stdout
