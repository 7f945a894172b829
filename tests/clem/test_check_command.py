"""`sartco check-instances FILE` (sartco.clem.check): the check `clem run` makes before any model
is asked, as a command: exit 0 and one line for a playable file, exit 2 and one line naming the
file, the episode and the field for a broken one."""
import json
import shutil
import sys
from pathlib import Path

import pytest

from forkserver import command

from sartco.cli import main

REPO = Path(__file__).resolve().parents[2]
GAME = REPO / "games" / "cobot_instruct"
SMOKE = json.loads((GAME / "in" / "instances_smoke.json").read_text(encoding="utf-8"))
SECOND = SMOKE["experiments"][1]  # its episodes: game_id 0 and 1


@pytest.fixture
def game_in(tmp_path):
    """The in/ folder of a copy of cobot_instruct (master.py and clemgame.json beside it)."""
    folder = tmp_path / "games" / "cobot_instruct"
    (folder / "in").mkdir(parents=True)
    shutil.copy(GAME / "master.py", folder)
    shutil.copy(GAME / "clemgame.json", folder)
    return folder / "in"


def check(capsys, *argv):
    code = main(["check-instances", *map(str, argv)])
    out, err = capsys.readouterr()
    return code, out.strip().splitlines(), err.strip().splitlines()


def broken(change):
    data = json.loads(json.dumps(SMOKE))
    change(data["experiments"][1]["game_instances"][1])
    return json.dumps(data)


def test_a_good_file_passes_with_one_line(capsys):
    path = GAME / "in" / "instances_smoke.json"
    code, out, err = check(capsys, path)
    assert (code, err) == (0, [])
    assert out == [f"{path}: 10 episodes (all experiments) fine for game cobot_instruct"]


def test_the_command_exits_0_and_2():
    """The installed `sartco` script: the exit codes a shell script reads."""
    sartco = str(Path(sys.executable).parent / "sartco")
    good = command([sartco, "check-instances", "games/cobot_instruct/in/instances_smoke.json"],
                   cwd=REPO, capture_output=True, text=True, timeout=300)
    assert good.returncode == 0 and len(good.stdout.splitlines()) == 1, good.stdout + good.stderr
    bad = command([sartco, "check-instances", "games/cobot_instruct/in/instances_smoke.json", "-e", "nope"],
                  cwd=REPO, capture_output=True, text=True, timeout=300)
    assert bad.returncode == 2 and "no experiment 'nope'" in bad.stderr and not bad.stdout


BAD = {
    # name: (file text, what the one line says after the file's path)
    "bad value": (broken(lambda ep: ep.update(rows=9)),
                  f"experiment {SECOND['name']}, game_id 1: field 'rows' is 9, expected 8"),
    "bad colour": (broken(lambda ep: ep.update(target={"0:0": [["washer", "purple"]]})),
                   f"experiment {SECOND['name']}, game_id 1: target cell \"0:0\": unknown colour \"purple\""),
    "missing field": (broken(lambda ep: ep.pop("target")),
                      f"experiment {SECOND['name']}, game_id 1: missing field 'target'"),
    "wrong type": (broken(lambda ep: ep.update(turns="one")),
                   f"experiment {SECOND['name']}, game_id 1: field 'turns' is str \"one\", expected a list"),
    "not JSON": (json.dumps(SMOKE)[:3000], "not valid JSON, truncated or broken at line 1 column "),
}


@pytest.mark.parametrize("case", BAD, ids=BAD)
def test_a_broken_file_exits_2_naming_what_is_wrong(game_in, capsys, case):
    text, expected = BAD[case]
    path = game_in / "instances.json"
    path.write_text(text)
    code, out, err = check(capsys, path)
    assert (code, out) == (2, [])
    assert len(err) == 1 and err[0].startswith(f"sartco check-instances: {path}: {expected}")


def test_the_game_by_name_for_a_file_anywhere(tmp_path, capsys, monkeypatch):
    """A file outside a game folder needs -g (found as clem run -g finds games); without it, one
    line says so."""
    path = tmp_path / "mine.json"
    path.write_text(json.dumps(SMOKE))
    monkeypatch.chdir(REPO)
    code, out, err = check(capsys, path, "-g", "cobot_instruct", "-e", SECOND["name"])
    assert (code, err) == (0, [])
    assert out == [f"{path}: 2 episodes (experiment {SECOND['name']}) fine for game cobot_instruct"]
    code, out, err = check(capsys, path)
    assert (code, out) == (2, [])
    assert err == [f"sartco check-instances: {path}: not in the in/ folder of a game; name its game with -g"]
    code, out, err = check(capsys, path, "-g", "no_such_game")
    assert (code, err) == (2, [f"sartco check-instances: no game 'no_such_game' in the game registry of {REPO}"])


def test_the_describe_game_checks_its_own_fields(game_in, capsys):
    """The fields are the game's: a cobot_instruct file is not a cobot_describe file."""
    describe = REPO / "games" / "cobot_describe"
    code, out, err = check(capsys, describe / "in" / "instances_slice.json")
    assert code == 0 and out[0].endswith("6 episodes (all experiments) fine for game cobot_describe")
    mixed = describe / "in" / "instances_slice.json"
    (game_in / "instances.json").write_text(mixed.read_text())
    code, out, err = check(capsys, game_in / "instances.json")
    assert code == 2 and "missing field 'source'" in err[0]
