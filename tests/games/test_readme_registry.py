"""The game_registry.json examples of docs/models.md (section "Running from a clembench checkout"),
read out of the page so the test follows it: each, with the page's placeholder path made this
checkout's, lets `clem list games` list our games in a folder of its own."""
import json
import os
import re
import sys
from pathlib import Path

import pytest

from forkserver import command

REPO = Path(__file__).resolve().parents[2]
CLEM = str(Path(sys.executable).parent / "clem")
PAGE = REPO / "docs" / "models.md"
SECTION = "## Running from a clembench checkout"
PLACEHOLDER = "/path/to/sartco-bench"


def registry_examples() -> list[list[dict]]:
    """The JSON blocks of the page's section, in order."""
    text = PAGE.read_text(encoding="utf-8")
    section = text[text.index(SECTION):]
    section = section[:section.index("\n## ", len(SECTION))]
    return [json.loads(block) for block in re.findall(r"```json\n(.*?)```", section, re.S)]


EXAMPLES = registry_examples()


def test_the_section_has_both_kinds_of_entry():
    keys = [set().union(*entries) for entries in EXAMPLES]
    assert len(EXAMPLES) == 2 and "benchmark_path" in keys[0] and "game_path" in keys[1]


@pytest.mark.parametrize("entries", EXAMPLES, ids=["benchmark_path", "game_path"])
def test_clem_list_games_with_the_documented_registry(tmp_path, entries):
    text = json.dumps(entries).replace(PLACEHOLDER, str(REPO))
    (tmp_path / "game_registry.json").write_text(text)
    env = {k: v for k, v in os.environ.items() if k != "CLEMBENCH_HOME"}
    done = command([CLEM, "list", "games"], cwd=tmp_path, env=env, capture_output=True, text=True,
                   timeout=300)
    assert done.returncode == 0 and "Traceback" not in done.stderr, done.stdout[-1500:] + done.stderr[-1500:]
    listed = re.findall(r"^ ?(\w+):$", done.stdout, re.M)
    expected = {e["game_name"] for e in entries if "game_name" in e} or {
        spec["game_name"] for clemgame in (REPO / "games").glob("*/clemgame.json")
        for spec in json.loads(clemgame.read_text())}
    assert set(listed) == expected
