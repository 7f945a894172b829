"""Board pictures for clemcore transcripts.

Every 'board' event of an episode (one per attempt: attempt 1 in every episode, 2, 3, ... in the
feedback experiments) shows `<img src="boards_<k>.svg">`, a path relative to the episode folder
where transcript.html is written (sartco.clem.building.log_build), so a copied or published
results folder keeps its pictures. The game master does not know its episode folder while
playing, so the files are written when the episode is scored (`clem score`, which runs before
`clem transcribe`): `attach_pictures` draws target beside built board (differing cells framed)
as boards_<k>.svg for every attempt (the records under `sartco_attempts`, or the final build
alone) and boards.svg for the final build. Browsers show SVG in <img>, so no PNG is needed.
"""
from __future__ import annotations

import json
import logging
from pathlib import Path

from sartco.episode import ATTEMPTS_KEY, BUILD_KEY
from sartco.world import DEFAULT_COLS, DEFAULT_ROWS
from sartco.world.render import diff_svg

from .building import ATTEMPT_PICTURE, PICTURE

log = logging.getLogger(__name__)


def attach_pictures(interactions_file: str | Path) -> bool:
    """Write the board pictures of one episode beside its interactions.json; False when the
    episode has no build record (nothing to draw)."""
    interactions_file = Path(interactions_file)
    interactions = json.loads(interactions_file.read_text(encoding="utf-8"))
    record = interactions.get(BUILD_KEY)
    if record is None:
        return False
    folder = interactions_file.parent
    final = _svg(record)
    (folder / PICTURE).write_text(final, encoding="utf-8")
    for k, attempt in enumerate(interactions.get(ATTEMPTS_KEY) or [record], 1):  # the last is usually the final
        (folder / ATTEMPT_PICTURE.format(k)).write_text(final if attempt == record else _svg(attempt), encoding="utf-8")
    return True


def _svg(record: dict) -> str:
    """Target beside built board (differing cells framed), as SVG."""
    return diff_svg(record["target"], record["cells"], record.get("rows", DEFAULT_ROWS), record.get("cols", DEFAULT_COLS))


def attach_all(interaction_files) -> int:
    """attach_pictures for many episodes; a broken episode is logged and skipped."""
    done = 0
    for path in interaction_files:
        try:
            done += attach_pictures(path)
        except Exception:  # one bad episode must not stop scoring
            log.exception("cannot draw the boards of %s", path)
    return done
