"""Board pictures for clemcore transcripts.

clemcore's transcript builder shows `action["image"]` paths of an event as <img> tags (absolute
paths kept, relative ones resolved against the installed clemcore), and browsers show SVG in
<img>, so no PNG is needed. The game master does not know its episode folder while playing, so
the pictures are written when the episode is scored (`clem score`, which runs before `clem
transcribe`): `attach_pictures` writes boards.svg (target beside built, differing cells framed)
next to interactions.json and links it, by absolute path, into the episode's 'board' event.
Re-scoring after moving a results folder rewrites the links.
Feedback experiments (every attempt logged under `sartco_attempts`, one board event each):
boards_1.svg, boards_2.svg, ... one per attempt, linked to that attempt's board event; boards.svg
is still written for the final build.
"""
from __future__ import annotations

import json
import logging
from pathlib import Path

from sartco.world import DEFAULT_COLS, DEFAULT_ROWS
from sartco.world.render import diff_svg

from .building import ATTEMPTS_KEY, BOARD_EVENT, BUILD_KEY

log = logging.getLogger(__name__)
PICTURE = "boards.svg"
ATTEMPT_PICTURE = "boards_{}.svg"  # attempt 1, 2, ...


def attach_pictures(interactions_file: str | Path) -> bool:
    """Write the board picture of one episode and link it into its board event; False when the
    episode has no build record (nothing to draw)."""
    interactions_file = Path(interactions_file)
    interactions = json.loads(interactions_file.read_text(encoding="utf-8"))
    record = interactions.get(BUILD_KEY)
    if record is None:
        return False
    folder = interactions_file.parent
    picture = _draw(folder / PICTURE, record)
    events = [e for turn in interactions.get("turns", []) for e in turn
              if e.get("from") == "GM" and e.get("to") == "GM" and e.get("action", {}).get("type") == BOARD_EVENT]
    attempts = interactions.get(ATTEMPTS_KEY) or []
    if attempts:
        links = [[str(_draw(folder / ATTEMPT_PICTURE.format(k), a))] for k, a in enumerate(attempts, 1)]
    else:
        links = [[str(picture)]]
    if not events:
        return True
    changed = False
    # the last events are the attempts' (a game logs one board event per attempt, in order)
    for event, link in zip(events[-len(links):], links[-len(events):]):
        if event["action"].get("image") != link:
            event["action"]["image"] = link
            changed = True
    if changed:
        interactions_file.write_text(json.dumps(interactions, indent=2, ensure_ascii=False), encoding="utf-8")
    return True


def _draw(path: Path, record: dict) -> Path:
    """Target beside built board (differing cells framed), as SVG at `path`; the absolute path."""
    path = path.resolve()
    path.write_text(diff_svg(record["target"], record["cells"], record.get("rows", DEFAULT_ROWS), record.get("cols", DEFAULT_COLS)),
                    encoding="utf-8")
    return path


def attach_all(interaction_files) -> int:
    """attach_pictures for many episodes; a broken episode is logged and skipped."""
    done = 0
    for path in interaction_files:
        try:
            done += attach_pictures(path)
        except Exception:  # one bad episode must not stop scoring
            log.exception("cannot draw the boards of %s", path)
    return done
