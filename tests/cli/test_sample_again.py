"""`sartco sample`'s advice after a failed sample works (issue 44): the same command again
completes that sample (by `sartco resume`, which transcribes) and plays the ones still missing."""
from __future__ import annotations

import json

from play_helpers import REPO, sartco

ARGS = ["sample", "-g", "cobot_instruct", "-m", "mock", "-n", "2", "-t", "0", "-i", "instances_smoke",
        "-e", "sb_so_first_order_template"]


def test_the_same_sample_command_again_completes_a_failed_sample(tmp_path, monkeypatch):
    from clemcore import cli as clem_cli

    real = clem_cli.run

    def fails_in_sample_1(*args, **kwargs):   # one episode played, then clemcore's exit after an exception
        if "/samples/s1" in str(kwargs["results_dir_path"]):
            real(*args, **{**kwargs, "instances_filter": lambda row: row["game_instance"]["game_id"] == 0})
            raise SystemExit(1)
        return real(*args, **kwargs)

    monkeypatch.setattr(clem_cli, "run", fails_in_sample_1)
    failed = sartco(*ARGS, "-r", tmp_path)
    assert failed.returncode == 2
    assert "run the same `sartco sample` command again: it completes that sample" in failed.stderr
    monkeypatch.setattr(clem_cli, "run", real)
    done = sartco(*ARGS, "-r", tmp_path)
    assert done.returncode == 0, done.stdout + done.stderr
    scores = {k: sorted(json.loads(p.read_text().replace("NaN", "null"))["episode scores"].items())
              for k in ("s1", "s2")
              for p in [tmp_path / "samples" / k / "mock" / "cobot_instruct" / "sb_so_first_order_template" /
                        "instance_00001" / "scores.json"]}
    assert scores["s1"] == scores["s2"]
    assert (tmp_path / "samples" / "s1" / "mock" / "cobot_instruct" / "sb_so_first_order_template" / "instance_00001"
            / "transcript.html").is_file()
    assert REPO.is_dir()
