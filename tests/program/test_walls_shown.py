"""Which walls held is shown where a run is read (issue 42): `sartco execute` on stderr (its
stdout stays JSON lines) and run.json's `walls`."""
import json
import subprocess
import sys

from sartco.clem.core.provenance import environment

NAMES = ["seccomp", "rlimits", "environment", "user namespace", "pid namespace", "net namespace", "ipc namespace",
         "uts namespace", "mount namespace"]


def test_sartco_execute_says_which_walls_hold():
    line = json.dumps({"id": "a", "code": "put(board, 'nut', 'red', 0, 0)"}) + "\n"
    done = subprocess.run([sys.executable, "-m", "sartco", "execute"], input=line, capture_output=True, text=True,
                          timeout=120)
    assert done.returncode == 0, done.stderr
    assert json.loads(done.stdout)["ok"] is True
    assert done.stderr.startswith("walls: seccomp, rlimits, environment"), done.stderr


def test_run_json_records_the_walls():
    walls = environment()["walls"]
    assert [w["name"] for w in walls] == NAMES
    assert all(set(w) == {"name", "up", "why"} and type(w["up"]) is bool and w["why"] for w in walls)
    assert walls[0]["up"] and walls[1]["up"]
