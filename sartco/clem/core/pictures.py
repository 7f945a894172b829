"""Full-size board pictures beside an episode's records.

Every 'board' event of an episode (one per attempt: attempt 1 in every episode, 2, 3, ... in the
feedback experiments) carries its picture inside the event (a data: URL drawn by the game master
while playing, sartco.clem.core.building.record_build), so `clem transcribe` shows it whether or not
`clem score` ran first; the picture links to `boards_<k>.svg`, a path relative to the episode
folder where transcript.html is written, so a copied or published results folder keeps its links.
The game master does not know its episode folder while playing, so these files are written when
the episode is scored (`clem score`): `attach_pictures` draws target beside built board
(sartco.world.render.diff_svg) as boards_<k>.svg for every attempt (the records under
`sartco_attempts`, or the final build alone) and boards.svg for the final build.
"""
from __future__ import annotations

import json
import logging
from pathlib import Path

from sartco.episode import ATTEMPTS_KEY, BUILD_KEY
from .building import ATTEMPT_PICTURE, PICTURE, BuildRecord

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
    return BuildRecord.from_json(record).svg()


def attach_all(interaction_files) -> int:
    """attach_pictures for many episodes; a broken episode is logged and skipped."""
    done = 0
    for path in interaction_files:
        try:
            done += attach_pictures(path)
        except Exception:  # one bad episode must not stop scoring
            log.exception("cannot draw the boards of %s", path)
    return done
