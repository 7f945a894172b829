"""Board pictures for clemcore transcripts.

clemcore's transcript builder shows `action["image"]` paths of an event as <img> tags (absolute
paths kept, relative ones resolved against the installed clemcore), and browsers show SVG in
<img>, so no PNG is needed. The game master does not know its episode folder while playing, so
the pictures are written when the episode is scored (`clem score`, which runs before `clem
transcribe`): `attach_pictures` writes boards.svg (target beside built, differing cells framed)
next to interactions.json and links it, by absolute path, into the episode's 'board' event.
Re-scoring after moving a results folder rewrites the links.
"""
from __future__ import annotations

import json
import logging
from pathlib import Path

from sartco.world.render import diff_svg

from .building import BOARD_EVENT, BUILD_KEY

log = logging.getLogger(__name__)
PICTURE = "boards.svg"


def attach_pictures(interactions_file: str | Path) -> bool:
    """Write the board picture of one episode and link it into its board event; False when the
    episode has no build record (nothing to draw)."""
    interactions_file = Path(interactions_file)
    interactions = json.loads(interactions_file.read_text(encoding="utf-8"))
    record = interactions.get(BUILD_KEY)
    if record is None:
        return False
    picture = (interactions_file.parent / PICTURE).resolve()
    picture.write_text(diff_svg(record["target"], record["cells"], record.get("rows", 8), record.get("cols", 8)),
                       encoding="utf-8")
    events = [e for turn in interactions.get("turns", []) for e in turn
              if e.get("from") == "GM" and e.get("to") == "GM" and e.get("action", {}).get("type") == BOARD_EVENT]
    if not events:
        return True
    action = events[-1]["action"]
    if action.get("image") != [str(picture)]:
        action["image"] = [str(picture)]
        interactions_file.write_text(json.dumps(interactions, indent=2, ensure_ascii=False), encoding="utf-8")
    return True


def attach_all(interaction_files) -> int:
    """attach_pictures for many episodes; a broken episode is logged and skipped."""
    done = 0
    for path in interaction_files:
        try:
            done += attach_pictures(path)
        except Exception:  # one bad episode must not stop scoring
            log.exception("cannot draw the boards of %s", path)
    return done
