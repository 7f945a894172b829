"""`sartco export-dataset`: cobot_instruct episodes as a dataset trainers load directly.

    sartco export-dataset [--instances FILE ...] --out DIR [--parquet]
    -> DIR/<instance file stem>.jsonl (and .parquet): one row per episode, in file order
    datasets.load_dataset("json", data_files="DIR/instances_train.jsonl", split="train")

Default input: the train split, games/cobot_instruct/in/instances_train.json (`sartco instances
instruct-train` writes it); any cobot_instruct instance file of our protocol can be given.

A row (the same keys in every row, so Arrow gives every column one type):
  id          "<experiment>/<board id>/<task>": the episode id of sartco.reward.score
  prompt      the chat messages of the game's first turn, exactly as the Builder receives them:
              [{"role": "user", "content": <the episode's first turn>}] (TRL's conversational
              "prompt" column)
  turns       the episode's number of turns (1: the function and repetition cells; first_order:
              one per instruction, the later ones come from the game: sartco.games.instruct.training)
  experiment, game_id, board_id, task, board_type, object_type, source, split
  episode     the episode as the game holds it (its instance, JSON text): what the scorer needs;
              `sartco.reward.Episodes.from_rows(rows)` reads the episodes back from rows
--parquet also writes the rows as parquet (needs pyarrow, which clemcore's `datasets` brings).
"""
from __future__ import annotations

import json
from pathlib import Path

from sartco.errors import UserError
from sartco.protocols import INSTANCES_DIR, file_episodes

from .core import Episodes

TRAIN_FILE = INSTANCES_DIR / "instances_train.json"
ROW_FIELDS = ("id", "prompt", "turns", "experiment", "game_id", "board_id", "task", "board_type", "object_type",
              "source", "split", "episode")


def configure(parser) -> None:
    parser.add_argument("--instances", type=Path, action="append", default=None, metavar="FILE",
                        help=f"cobot_instruct instance file (repeatable; default {TRAIN_FILE})")
    parser.add_argument("--out", type=Path, required=True, help="folder of the dataset files")
    parser.add_argument("--parquet", action="store_true", help="also write <stem>.parquet (pyarrow)")


def rows_of(path: Path) -> list[dict]:
    """One row per episode of an instance file (module doc), in file order."""
    experiments = {e["name"]: e for e in json.loads(Path(path).read_text(encoding="utf-8"))["experiments"]}
    rows = []
    for episode in file_episodes(path):
        instance, experiment = episode["instance"], experiments[episode["file"]]
        rows.append({
            "id": episode["id"], "prompt": [{"role": "user", "content": instance["turns"][0]}],
            "turns": len(instance["turns"]), "experiment": episode["file"], "game_id": instance["game_id"],
            "board_id": instance["board_id"], "task": instance["task"], "board_type": instance["board_type"],
            "object_type": instance["object_type"], "source": instance.get("source", experiment.get("source", "")),
            "split": experiment.get("split", ""), "episode": json.dumps(instance, ensure_ascii=False),
        })
    return rows


def write_jsonl(rows: list[dict], path: Path) -> None:
    with open(path, "w", encoding="utf-8") as out:
        for row in rows:
            out.write(json.dumps(row) + "\n")  # ASCII: every text exactly as the game holds it


def write_parquet(rows: list[dict], path: Path) -> None:
    try:
        import pyarrow as pa
        import pyarrow.parquet as pq
    except ImportError:
        raise UserError("--parquet needs pyarrow (pip install pyarrow); the JSON lines were written") from None
    pq.write_table(pa.Table.from_pylist(rows), path)


def run(args) -> int:
    files = args.instances or [TRAIN_FILE]
    for path in files:
        if not Path(path).is_file():
            hint = " (write it with `sartco instances instruct-train`)" if Path(path) == TRAIN_FILE else ""
            raise UserError(f"{path}: no such instance file{hint}")
    Episodes.from_files(files)  # every file readable, every id once (a UserError before anything is written)
    args.out.mkdir(parents=True, exist_ok=True)
    written = []
    for path in files:
        rows = rows_of(Path(path))
        write_jsonl(rows, args.out / f"{Path(path).stem}.jsonl")
        written.append(f"{args.out / Path(path).stem}.jsonl ({len(rows)} rows)")
    if args.parquet:  # after every JSON lines file: a missing pyarrow loses none of them
        for path in files:
            write_parquet(rows_of(Path(path)), args.out / f"{Path(path).stem}.parquet")
            written.append(f"{args.out / Path(path).stem}.parquet")
    print("sartco export-dataset: wrote " + ", ".join(written))
    return 0
