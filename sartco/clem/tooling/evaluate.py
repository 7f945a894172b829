"""`clem eval` for a list of game/model pairs, in one process: the files that

    rm -f RESULTS/raw.csv
    for each (game, model) in pairs:  clem eval -r RESULTS -g game -m model

write (raw.csv, results.csv, results.html), byte for byte, built by clemcore's own clemeval
functions (load_scores, save_clem_table) and its own steps of perform_evaluation, in a fraction
of the time. `clem eval` stays the documented command; this is what `sartco suite` (make main)
calls after playing (tests/clem/test_evaluate.py compares the files with `clem eval`'s).

Where the time of the loop above goes, and what is done instead:
- every `clem eval` imports clemcore (about 4 s) and looks for score files in the whole folder:
  here one import, one walk (`score_files`), the same files in the same order for each pair;
- clemeval.build_df_episode_scores adds one row at a time (`df.loc[len(df)] = row`), which copies
  the frame each time, so its cost grows with the square of a pair's rows. `episode_frame` builds
  the same frame: the same values with the same dtypes. The frame's value column is what row-wise
  enlargement makes it, and pandas may recast it while it grows (int64 -> float64 -> object, a
  bool recast to a number; an object column of missing values only taking the next value's
  type), so the rows are added with that very `.loc` enlargement until the column is `object`
  and holds a value; from there on pandas keeps every value as it is given, and the rest is
  added at once as object columns.
- raw.csv is written and read back by every `clem eval` (pandas infers the columns' types again
  on each read): the same round trips happen here, in memory, and only the last is written.
"""
from __future__ import annotations

import io
import os
from pathlib import Path

import pandas as pd
from pandas.api.types import is_object_dtype
from clemcore import clemeval
import clemcore.clemgame.metrics as clemmetrics

COLUMNS = ["game", "model", "experiment", "episode", "metric", "value"]


def score_files(results_dir: str | Path) -> list[Path]:
    """Every score file as clemeval.load_scores finds it (its rglob, its order)."""
    return list(Path(results_dir).rglob("*scores.json"))


def selected(files: list[Path], model: str | None, game: str | None) -> list[Path]:
    """load_scores' selection: the model's name anywhere in the path, the game's as a part of it."""
    return [f for f in files if (model is None or model in str(f)) and (game is None or game in f.parts)]


def load(files: list[Path]) -> dict:
    """clemeval.load_scores over given files: {(game, model, experiment, episode): {"episodes": ...}}."""
    scores: dict = {}
    for path in files:
        naming = clemeval.name_as_tuple(clemeval.parse_directory_name(path))
        if naming not in scores:
            scores[naming] = {"episodes": clemeval.load_json(path)["episode scores"]}
    return scores


def episode_frame(scores: dict) -> pd.DataFrame:
    """The frame clemeval.build_df_episode_scores builds (module doc), without its quadratic cost."""
    rows = [[*name, metric, value] for name, data in scores.items() for metric, value in data["episodes"].items()]
    frame = pd.DataFrame(columns=COLUMNS)
    k = 0
    while k < len(rows) and not (is_object_dtype(frame["value"]) and frame["value"].notna().any()):
        frame.loc[len(frame)] = rows[k]  # clemeval's own way, while pandas may still recast the column
        k += 1
    if k == len(rows):
        return frame
    rest = pd.DataFrame(rows[k:], columns=COLUMNS, dtype=object, index=range(k, len(rows)))
    return pd.concat([frame, rest])


def _with_played(frame: pd.DataFrame) -> pd.DataFrame:
    """perform_evaluation's METRIC_PLAYED rows (1 - aborted), added after the episode rows."""
    if clemmetrics.METRIC_PLAYED in frame["metric"].unique():
        raise clemeval.PlayedScoreError("Computed scores should not contain METRIC_PLAYED.")
    aux = frame[frame["metric"] == clemmetrics.METRIC_ABORTED].copy()
    aux["metric"] = clemmetrics.METRIC_PLAYED
    aux["value"] = 1 - aux["value"]
    return pd.concat([frame, aux], ignore_index=True)


def _body(frame: pd.DataFrame) -> list[str]:
    """The lines to_csv writes for a frame's rows, without the index."""
    return frame.to_csv(header=False, index=False).splitlines(keepends=True)


def evaluate(results_dir: str | Path, pairs: list[tuple[str, str]]) -> pd.DataFrame:
    """Write raw.csv, results.csv and results.html as `clem eval -g game -m model` for each pair in
    turn would, after raw.csv is removed (module doc); returns the results table.

    Each `clem eval` reads raw.csv back and writes all of it again. When pandas reads every column
    back as `object` (the scores hold text: categories, sources), each value it read is the text
    it wrote (a number's text parses back to the same number), so writing the old rows again gives
    their old text: only the new rows are formatted (with one old row beside them, so that pandas
    gives their columns the dtype of the whole frame), and the old lines are kept. Otherwise the
    whole frame is written, as clem eval does."""
    results_dir = str(results_dir)
    if not pairs:
        raise ValueError("evaluate: no game/model pairs")
    files = score_files(results_dir)
    header, lines = "", []  # raw.csv so far: its header and its rows, without the index
    frame = None
    for game, model in pairs:
        new = _with_played(episode_frame(load(selected(files, model, game))))
        if frame is None:  # the first `clem eval`: no raw.csv yet, a full evaluation of the selection
            frame = new
            header, *rest = frame.to_csv(index=False).splitlines(keepends=True)
            lines = rest
            continue
        existing = pd.read_csv(io.StringIO(_text(header, lines)), index_col=0)
        mask = existing["model"].str.contains(model, na=False) & (existing["game"] == game)
        frame = pd.concat([existing[~mask], new], ignore_index=True)
        if all(is_object_dtype(dtype) for dtype in existing.dtypes) and len(existing) > int(mask.sum()):
            kept = [i for i, drop in enumerate(mask) if not drop]
            head = existing[~mask].iloc[:1]
            lines = [lines[i] for i in kept] + _body(pd.concat([head, new], ignore_index=True))[1:]
        else:
            header, *lines = frame.to_csv(index=False).splitlines(keepends=True)
    assert frame is not None
    with open(os.path.join(results_dir, "raw.csv"), "w") as f:
        f.write(_text(header, lines))
    return clemeval.save_clem_table(frame, results_dir)


def _text(header: str, lines: list[str]) -> str:
    """raw.csv's text: to_csv's, with the index (0, 1, ...) in front of each line."""
    return "," + header + "".join(f"{i},{line}" for i, line in enumerate(lines))
