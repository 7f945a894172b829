"""The tests' command processes (tests/forkserver.py): a command forked from the warm server
says, writes and exits as the same command in a fresh interpreter does."""
import os
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


def test_the_commands_of_the_tests_agree(tmp_path):
    bad = tmp_path / "bad.json"
    bad.write_text('{"experiments": [')
    for args, cwd, status in (([BIN / "clem", "list", "games"], REPO, 0),
                              ([sys.executable, "-m", "sartco", "check-instances", bad], tmp_path, 2)):
        fresh, forked = both(args, cwd=cwd)
        assert (forked.returncode, forked.stdout, forked.stderr) == (fresh.returncode, fresh.stdout, fresh.stderr), args
        assert fresh.returncode == status and (fresh.stdout + fresh.stderr).strip(), args


def test_clemcore_logs_in_the_commands_folder_and_the_server_imports_neither(tmp_path):
    done = command([BIN / "clem", "run", "-g", "cobot_instruct", "-m", "mock", "-i", "no_such_file"], cwd=tmp_path)
    assert done.returncode != 0
    assert (tmp_path / "clembench.log").is_file()  # clemcore's logging config, read in the child's folder
    server, _ = forkserver._start()
    assert server.poll() is None  # the server checked at its start that clemcore and sartco are not imported


def test_another_hash_seed_gets_a_fresh_process(tmp_path):
    code = [sys.executable, "-m", "sartco", "export-prompts", "--protocol", "paper", "--file", "sb_so_test_hc"]
    assert forkserver._python_args([str(a) for a in code]) == [str(a) for a in code[1:]]
    assert forkserver._fresh_enough(dict(os.environ))
    assert not forkserver._fresh_enough(dict(os.environ, PYTHONHASHSEED="123"))
    assert forkserver._python_args([sys.executable, "-c", "pass"]) is None  # -c: always fresh
