"""`sartco import-instructions -r RESULTS --out DIR`: the instructions that describers wrote in
cobot_describe episodes -> a dataset (docs/ARCHITECTURE.md format) whose records carry them as
an instruction source named after the describer model, as the paper did with the instructions
written by CodeLlama, GPT-4 and Claude.

Reads every RESULTS/**/cobot_describe/<experiment>/instance_*/ episode: the instruction the game
master passed to the builder (interactions.json, key sartco_instruction), the describer's model
name (interactions.json players, "Player 1") and the board record (instance.json, key record).
Writes one record per board: the board record with `instructions[<model>] = {"single_turn": text}`
(simple boards) or `{"regular": text}` (regular boards) for every model that described it, next
to the template instructions; the record keeps its id, so the base dataset's train split (named
in the manifest under config.base) still serves the in-context examples. Files:
`<board_type>_<object_type>_<split>.json` and manifest.json ({"source": "describer", ...}).

Only the `oneshot` experiments count (an experiment without a `mode` field is one): in the
dialogue modes the describer's first instruction comes from the same prompt, and what follows it
(answers, corrections) is not an instruction of the paper's kind.
Episodes without an instruction (the describer's answer had no "Instruction:"), unreadable
episodes and repeated (model, board) pairs are left out and listed in the manifest's defects.
"""
from __future__ import annotations

import argparse
import copy
import json
from collections import Counter, defaultdict
from pathlib import Path

from sartco.dataset import BOARD_KINDS, DESCRIBED_TASK, INSTRUCTION_STYLE, board_kind
from sartco.errors import UserError

from .storage import FORMAT, dumps, make_folder

GAME = "cobot_describe"


def _read_json(path: Path):
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except FileNotFoundError:
        return None
    except (OSError, UnicodeDecodeError, json.JSONDecodeError) as exc:
        raise ValueError(f"{path.name}: {exc}") from None


def episodes(results: Path) -> list[Path]:
    """The episode folders of cobot_describe below results, in a stable order."""
    return sorted(p.parent for p in results.rglob("interactions.json")
                  if p.parent.name.startswith("instance_") and p.parent.parent.parent.name == GAME)


def _defect(kind: str, episode: Path, results: Path, detail: str, **extra) -> dict:
    return {"kind": kind, "episode": str(episode.relative_to(results)), "detail": detail, **extra}


def collect(results: Path) -> tuple[dict[str, dict], list[dict], dict]:
    """board id -> record with the describers' instructions; defects; base datasets seen."""
    records: dict[str, dict] = {}
    defects: list[dict] = []
    bases: set[tuple] = set()
    found = episodes(results)
    if not found:
        raise UserError(f"-r {results}: no {GAME} episodes found (expected "
                        f"<run>/{GAME}/<experiment>/instance_*/interactions.json below it)")
    for episode in found:
        try:
            interactions = _read_json(episode / "interactions.json")
            instance = _read_json(episode / "instance.json")
            experiment = _read_json(episode.parent / "experiment.json") or {}
        except ValueError as exc:
            defects.append(_defect("unreadable", episode, results, str(exc)))
            continue
        if (experiment.get("mode") or "oneshot") != "oneshot":
            continue  # the dialogue modes: the same first instruction again, then answers and corrections
        if not isinstance(instance, dict) or not isinstance(instance.get("record"), dict):
            defects.append(_defect("no_record", episode, results, "instance.json missing or without the board record"))
            continue
        model = ((interactions.get("players") or {}).get("Player 1") or {}).get("model_name")
        said = interactions.get("sartco_instruction") or {}
        record = instance["record"]
        if not model:
            defects.append(_defect("no_model", episode, results, "interactions.json names no describer model"))
            continue
        if not said.get("text"):
            reason = said.get("error") or "the episode recorded no instruction"
            defects.append(_defect("no_instruction", episode, results, reason, model=model, board=record["id"]))
            continue
        merged = records.setdefault(record["id"], copy.deepcopy(record))
        if model in merged["instructions"]:
            defects.append(_defect("duplicate", episode, results, "this model already described this board; first kept",
                                   model=model, board=record["id"]))
            continue
        style = INSTRUCTION_STYLE[DESCRIBED_TASK[record["board_type"]]]  # single_turn | regular
        merged["instructions"][model] = {style: said["text"]}
        prov = merged["provenance"]
        if prov.get("source") != "describer":
            merged["provenance"] = prov = {"source": "describer", "record": prov, "episodes": {}}
        prov["episodes"][model] = str(episode.relative_to(results))
        if "dataset" in experiment:
            bases.add((experiment["dataset"], experiment.get("dataset_seed")))
    return records, defects, {"bases": sorted(bases, key=str), "episodes": len(found)}


def import_instructions(results: Path, out: Path, version: str) -> dict:
    if not results.is_dir():
        raise UserError(f"-r {results}: not a folder")
    records, defects, info = collect(results)
    if not records:
        kinds = Counter(d["kind"] for d in defects)
        raise UserError(f"-r {results}: no describer instructions in {info['episodes']} {GAME} episodes "
                        f"({', '.join(f'{n} {k}' for k, n in sorted(kinds.items()))})")
    files: dict[str, list[dict]] = defaultdict(list)
    order = {}  # file name -> (board kind, name): the kinds in their order, a kind's splits by name
    for record in records.values():
        kind = board_kind(record["board_type"], record["object_type"])
        name = kind.dataset_file(record["split"])
        files[name].append(record)
        order[name] = (BOARD_KINDS.index(kind), name)
    names = sorted(files, key=order.__getitem__)
    make_folder(out)
    for name in names:
        (out / name).write_text(dumps(sorted(files[name], key=lambda r: r["id"])), encoding="utf-8")
    sources = Counter(m for r in records.values() for m in r["provenance"]["episodes"])
    manifest = {
        "format": FORMAT, "version": version, "source": "describer", "seed": None,
        "config": {"results": str(results), "episodes_read": info["episodes"],
                   "base": [{"version": v, "seed": s} for v, s in info["bases"]],
                   "instruction_sources": dict(sorted(sources.items()))},
        "files": {name: len(files[name]) for name in names},
        "defects": defects,
    }
    (out / "manifest.json").write_text(dumps(manifest), encoding="utf-8")
    return manifest


def configure(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("-r", "--results", type=Path, required=True, metavar="RESULTS",
                        help="clemcore results folder with cobot_describe episodes")
    parser.add_argument("--out", type=Path, required=True, metavar="DIR", help="dataset folder to write")
    parser.add_argument("--version", default="describers", help="the dataset's version name (default: describers)")


def run(args: argparse.Namespace) -> int:
    manifest = import_instructions(args.results, args.out, args.version)
    print(f"read {manifest['config']['episodes_read']} {GAME} episodes from {args.results}")
    for name, n in manifest["files"].items():
        print(f"  {args.out}/{name}: {n} boards")
    for model, n in manifest["config"]["instruction_sources"].items():
        print(f"  source {model!r}: {n} instructions")
    kinds = Counter(d["kind"] for d in manifest["defects"])
    print(f"left out: {len(manifest['defects'])} episodes" + "".join(f", {n} {k}" for k, n in sorted(kinds.items())))
    return 0
