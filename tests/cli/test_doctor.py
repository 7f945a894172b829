"""`sartco doctor` (issue 44): one line each, exit 0 when make main has what it needs; the walls
that hold here and on a machine without libseccomp; whether a model server answers."""
from __future__ import annotations

import json
import os
import sys
from pathlib import Path

from forkserver import command
from sartco.clem.tooling import benchrun
from sartco.clem.tooling.stub_server import StubServer

REPO = Path(__file__).resolve().parents[2]
BIN = Path(sys.executable).parent


def test_doctor_says_what_this_machine_can_do_and_whether_the_model_answers(tmp_path):
    with StubServer({}, latency=0.0) as server:
        benchrun.write_scratch(tmp_path, server.base_url, "openai_compatible", 1)
        registry = json.loads((tmp_path / "model_registry.json").read_text())
        registry += [{"model_name": "rulebased", "backend": "rulebased"}, {"model_name": "erring", "backend": "erring"}]
        (tmp_path / "model_registry.json").write_text(json.dumps(registry))
        done = command([BIN / "sartco", "doctor", "--timeout", "5"], cwd=tmp_path, env=benchrun.clem_env(), timeout=300)
    lines = done.stdout.splitlines()
    assert done.returncode == 0, done.stdout + done.stderr
    assert [line.split(":")[0] for line in lines] == ["python", "walls", "data", "registries",
                                                       f"model {benchrun.MODEL} (openai_compatible)", "games", "sartco doctor"]
    assert lines[1].startswith("walls: seccomp up; rlimits up; environment up; user namespace ")
    assert f"answers at {server.base_url}" in lines[4]
    assert "cobot_instruct" in lines[5] and "cobot_describe" in lines[5]
    with StubServer({}, latency=0.0, hang=True) as hung:
        benchrun.write_scratch(tmp_path, hung.base_url, "openai_compatible", 1)
        done = command([BIN / "sartco", "doctor", "--timeout", "0.5"], cwd=tmp_path, env=benchrun.clem_env(), timeout=300)
    assert f"no answer from {hung.base_url} within 0.5 s" in done.stdout   # said, not counted: make main needs none


def test_doctor_on_a_machine_without_libseccomp(tmp_path):
    hidden = tmp_path / "hidden"
    hidden.mkdir()
    (hidden / "pyseccomp.py").write_text('raise ImportError("libseccomp.so.2: cannot open shared object file")\n')
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(hidden), os.environ.get("PYTHONPATH", "")])}
    done = command([BIN / "sartco", "doctor"], cwd=REPO, env=env, timeout=300)
    assert done.returncode == 1, done.stdout + done.stderr
    walls = next(line for line in done.stdout.splitlines() if line.startswith("walls: "))
    assert walls.startswith("walls: seccomp down (libseccomp is not usable (libseccomp.so.2: cannot open shared object "
                            "file); install the system's libseccomp2")
    assert "rlimits down" in walls and "every episode harness_error" in walls
    assert done.stdout.splitlines()[-1] == "sartco doctor: something make main needs is missing (above)"
