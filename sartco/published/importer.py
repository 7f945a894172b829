"""`sartco import SRC_DIR --out DIR`: the published SARTCo files -> our dataset format.

Reads the 16 files the SARTCo authors released (../shared/sartco-data/published): the val/test
(and rb_so train) files with their template instructions, plus the test variants with human-written
(`_hc`) and model-written (`_mg` CodeLlama-34B, `_gpt4_mg`, `_claude_mg`) instructions. A variant
is its test file plus one dialogue key, so it is merged into the test file's records as one more
instruction source (sartco.published.samples). Output: docs/ARCHITECTURE.md "Datasets"
(manifest.json + one file per board kind and split).

Every gold program is run through the sandbox (sartco.instances.gold_code); the board it builds is
the record's target, and it must equal the authors' own board in gold_boards/ (the conformance
oracle). Defects of the published data are reported, never fatal (sartco.published.defects has
the rules); a file that cannot be read at all is a UserError naming file and field.
"""
from __future__ import annotations

import argparse
import hashlib
from collections import Counter
from dataclasses import asdict
from pathlib import Path
from typing import Any

from sartco.dataset import SOURCES, BoardRecord, PublishedName
from sartco.errors import UserError
from sartco.instances.gold_code import run_gold_code
from sartco.instances.storage import FORMAT, dumps, in_file_order, make_folder

from .defects import Defect, instruction_defects, judge_gold, overlap_defects
from .files import base_file, discover, gold_boards, read_samples
from .samples import SampleError, base_record, fingerprint, variant_texts


class Importer:
    def __init__(self, src: Path, gold_dir: Path | None):
        self.src = src
        self.gold_dir = gold_dir
        self.defects: list[Defect] = []
        self.records: dict[str, list[BoardRecord]] = {}   # output file -> records in order
        self.by_sample: dict[tuple[str, str], tuple[BoardRecord, str]] = {}  # (base file, sample) -> (record, fingerprint)
        self.read_counts: dict[str, int] = {}
        self.checked: Counter = Counter()                 # gold programs run / built their gold board

    def run(self) -> None:
        for path, name in discover(self.src):
            samples = read_samples(path)
            self.read_counts[path.name] = len(samples)
            if name.source == "template":
                self.read_base(path.name, name, samples)
            else:
                self.read_variant(path.name, name, samples)
        for records in self.records.values():
            for record in records:
                record["instructions"] = {s: record["instructions"][s] for s in SOURCES if s in record["instructions"]}
        self.defects += overlap_defects(self.files())

    def files(self) -> dict[str, list[BoardRecord]]:
        """The output files and their records, in file order."""
        return {name: self.records[name] for name in in_file_order(self.records)}

    def read_base(self, file: str, name: PublishedName, samples: list[tuple[str, Any]]) -> None:
        """A template file's samples as records, those whose gold programs build their board."""
        out = self.records.setdefault(name.kind.dataset_file(name.split), [])
        gold = gold_boards(self.gold_dir, file)
        if gold is None:
            self.defects.append(Defect("no_gold_board", file, None, None,
                                       "no gold_boards file; targets are not checked against the oracle"))
        pending = []
        for sample_path, sample in samples:
            try:
                pending.append((base_record(file, sample_path, sample, self.defects), fingerprint(sample, ())))
            except SampleError as exc:
                self.defects.append(Defect("malformed_sample", file, sample_path, None, str(exc)))
        runs = run_gold_code([record for record, _ in pending])
        for (record, sample_print), record_runs in zip(pending, runs):
            record["target"] = judge_gold(file, record, record_runs, gold, self.defects, self.checked)
            if record["target"] is not None:
                out.append(record)
                self.by_sample[(file, record["provenance"]["sample"])] = (record, sample_print)

    def read_variant(self, file: str, name: PublishedName, samples: list[tuple[str, Any]]) -> None:
        """A variant file's instructions, merged into its test file's records."""
        base = base_file(file)
        for sample_path, sample in samples:
            found = self.by_sample.get((base, sample_path))
            try:
                texts = variant_texts(file, sample_path, sample, found, self.defects)
            except SampleError as exc:
                self.defects.append(Defect("malformed_sample", file, sample_path, None, str(exc)))
                continue
            if texts is not None:
                found[0]["instructions"][name.source] = texts


def import_published(src: Path, out: Path, gold_dir: Path | None) -> dict:
    """Convert the published files in src into a dataset in out; returns the manifest. An --out that
    cannot be a folder is told before the files are read (reading runs every gold program)."""
    make_folder(out)
    importer = Importer(src, gold_dir)
    importer.run()
    files = importer.files()
    importer.defects += instruction_defects(files)
    for name, records in files.items():
        (out / name).write_text(dumps(records), encoding="utf-8")
    inputs = {name: hashlib.sha256((src / name).read_bytes()).hexdigest() for name in sorted(importer.read_counts)}
    manifest = {
        "format": FORMAT,
        "version": "published",
        "source": "published",
        "seed": None,
        "config": {
            "inputs": inputs,
            "samples_read": dict(sorted(importer.read_counts.items())),
            "gold_boards_checked": importer.checked["built_gold"],
            "gold_programs_run": importer.checked["run"],
        },
        "files": {name: len(records) for name, records in files.items()},
        "defects": [asdict(d) for d in importer.defects],
    }
    (out / "manifest.json").write_text(dumps(manifest), encoding="utf-8")
    return manifest


def summary(manifest: dict) -> str:
    config = manifest["config"]
    lines = ["read:"]
    lines += [f"  {name:28} {n:5} samples" for name, n in config["samples_read"].items()]
    lines.append("wrote:")
    lines += [f"  {name:28} {n:5} records" for name, n in manifest["files"].items()]
    lines.append(f"gold programs: {config['gold_programs_run']} run, {config['gold_boards_checked']} built their gold board")
    kinds = Counter(d["kind"] for d in manifest["defects"])
    lines.append(f"defects: {len(manifest['defects'])}" + ("" if kinds else " (none)"))
    lines += [f"  {kind:28} {n:5}" for kind, n in sorted(kinds.items())]
    return "\n".join(lines)


def configure(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("src", type=Path, metavar="SRC_DIR", help="folder with the published files (sb_so_test.json, ...)")
    parser.add_argument("--out", type=Path, required=True, metavar="DIR", help="dataset folder to write")
    parser.add_argument("--gold", type=Path, default=None, metavar="DIR",
                        help="the authors' gold boards (default: SRC_DIR/../gold_boards when it exists)")
    parser.add_argument("--quiet", action="store_true", help="print only the summary, not each defect")


def run(args: argparse.Namespace) -> int:
    gold = args.gold
    if gold is None:
        candidate = args.src / ".." / "gold_boards"
        gold = candidate if candidate.is_dir() else None
    elif not gold.is_dir():
        raise UserError(f"--gold {gold}: not a directory")
    manifest = import_published(args.src, args.out, gold)
    if not args.quiet:
        for d in manifest["defects"]:
            print(Defect(**d).line())
    print(summary(manifest))
    return 0
