"""pass@k of `sartco sample`'s runs: N samples of every episode in RESULTS/samples/s1..sN (each
an ordinary clemcore results folder), written by `sartco report -r RESULTS` as passk.md / .csv.

Per (model, game, experiment), over its episodes (matched by episode folder name across the
sample folders; n = the samples that have a scores.json and are no harness_error, c = those with
execution success 1; a harness_error sample, e.g. the model server gave no answer, is no
measurement of the model: it is left out of n and c, counted in the column harness_errors, and
`sartco report` exits with HARNESS_STATUS, naming the `sartco resume` of each sample folder):
  pass@k  the unbiased estimator of Chen et al. 2021 (Codex paper), 1 - C(n-c, k) / C(n, k):
          the chance that at least one of k samples drawn without replacement succeeds
  pass^k  C(c, k) / C(n, k): the chance that all k samples succeed
averaged over the episodes with at least k such samples, in percent, for k = 1, 5 and N (k > N
left out; NaN when no episode has k samples; the column samples gives the fewest an episode has,
fewer than N after a sample run that stopped early or a harness error). pass@1 = pass^1 = the
mean ES of the samples. A deterministic model (mock, rulebased) has c in {0, n} for every
episode, so its pass@k = pass^k = pass@1. A RESULTS folder that holds nothing but samples/ gets
passk.md / .csv alone.
"""
from __future__ import annotations

import sys
from collections import defaultdict
from collections.abc import Mapping, Sequence
from math import comb
from pathlib import Path
from typing import Any

from sartco.clem.tooling.sampling import SAMPLES  # RESULTS/samples/s1..sN

from .files import markdown_table, write_csv
from .rows import collect
from .harness_table import HARNESS_STATUS, is_harness


def pass_at_k(n: int, c: int, k: int) -> float:
    """Chen et al. 2021: 1 - C(n-c, k) / C(n, k) (NaN when k > n)."""
    if k > n:
        return float("nan")
    return 1.0 - comb(n - c, k) / comb(n, k)


def pass_all_k(n: int, c: int, k: int) -> float:
    """All k of k samples succeed: C(c, k) / C(n, k) (NaN when k > n)."""
    if k > n:
        return float("nan")
    return comb(c, k) / comb(n, k)


def sample_folders(results: Path) -> list[Path]:
    """RESULTS/samples/s1..sN in numeric order (empty when there are none)."""
    root = results / SAMPLES
    if not root.is_dir():
        return []
    found = [p for p in root.iterdir() if p.is_dir() and p.name[:1] == "s" and p.name[1:].isdigit()]
    return sorted(found, key=lambda p: int(p.name[1:]))


def counts(per_sample: Sequence[Sequence[Mapping[str, Any]]]) -> dict[tuple, dict[str, list[int]]]:
    """(model, game, experiment) -> episode -> [n, c, harness errors] from the episodes of each
    sample folder (a harness_error sample counts in neither n nor c)."""
    out: dict[tuple, dict[str, list[int]]] = defaultdict(lambda: defaultdict(lambda: [0, 0, 0]))
    for episodes in per_sample:
        for e in episodes:
            nc = out[(e["model"], e["game"], e["experiment"])][e["episode"]]
            if is_harness(e):
                nc[2] += 1
                continue
            nc[0] += 1
            nc[1] += int(e["es"] == 1)
    return out


def mean_percent(values: list[float]) -> float:
    return round(100 * sum(values) / len(values), 2) if values else float("nan")


def rows(table: dict[tuple, dict[str, list[int]]], ks: list[int]) -> list[dict]:
    out = []
    for (model, game, experiment), episodes in sorted(table.items()):
        ncs = [(n, c) for n, c, _ in episodes.values()]
        row = {"model": model, "game": game, "experiment": experiment, "episodes": len(ncs),
               "samples": min(n for n, _ in ncs), "harness_errors": sum(h for _, _, h in episodes.values())}
        for k in ks:  # over the episodes with at least k measured samples
            enough = [(n, c) for n, c in ncs if n >= k]
            row[f"pass@{k}"] = mean_percent([pass_at_k(n, c, k) for n, c in enough])
            row[f"pass^{k}"] = mean_percent([pass_all_k(n, c, k) for n, c in enough])
        out.append(row)
    return out


def samples_only(results: Path) -> bool:
    """RESULTS holds sample folders and no other run."""
    return bool(sample_folders(results)) and not any(p.is_dir() and p.name != SAMPLES for p in results.iterdir())


def write_alone(results: Path, out: Path) -> int:
    """`sartco report` of a folder with nothing but samples: passk.md / .csv; HARNESS_STATUS when a
    sample is a harness error, else 0."""
    out.mkdir(parents=True, exist_ok=True)
    written, faults = write(results, out)
    print("sartco report: samples only -> " + ", ".join(str(out / w) for w in written))
    return HARNESS_STATUS if faults else 0


def write(results: Path, out: Path) -> tuple[list[str], int]:
    """passk.md / passk.csv when RESULTS holds sample folders; (the names written, the harness
    error samples left out: a line on stderr names them and the command that plays them again)."""
    folders = sample_folders(results)
    if not folders:
        return [], 0
    per_sample = [collect(folder) for folder in folders]
    ks = sorted(k for k in {1, 5, len(folders)} if k <= len(folders))
    table = rows(counts(per_sample), ks)
    header = (["model", "game", "experiment", "episodes", "samples", "harness_errors"]
              + [f"{p}{k}" for k in ks for p in ("pass@", "pass^")])
    write_csv(out / "passk.csv", header, table)
    faults = sum(r["harness_errors"] for r in table)
    spoiled = [(f, e["model"], e["game"]) for f, episodes in zip(folders, per_sample) for e in episodes if is_harness(e)]
    md = (f"# pass@k over {len(folders)} samples per episode ({results / SAMPLES})\n\n"
          "pass@k = chance that at least one of k samples succeeds (execution success; unbiased estimator of "
          "Chen et al. 2021), pass^k = chance that all k succeed, in % over the episodes with at least k "
          "samples; samples = the fewest samples of an episode; NaN when no episode has k samples. A harness_error sample (the "
          "harness failed, not the model) is left out and counted in harness_errors.\n\n")
    if faults:
        fixes = sorted({f"sartco resume -r {folder} -g {game} -m {model}" for folder, model, game in spoiled})
        md = (f"> {faults} harness error sample(s) left out of pass@k (not the model's failures): play them "
              f"again with " + "; ".join(f"`{c}`" for c in fixes) + ".\n\n" + md)
        print(f"sartco report: pass@k: {faults} harness error sample(s) left out (the harness failed, not the "
              f"model); play them again: " + "; ".join(fixes) + f" (exit status {HARNESS_STATUS})", file=sys.stderr)
    (out / "passk.md").write_text(md + markdown_table(header, [[r[h] for h in header] for r in table]), encoding="utf-8")
    return ["passk.md", "passk.csv"], faults
