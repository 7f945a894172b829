"""pass@k of `sartco sample`'s runs: N samples of every episode in RESULTS/samples/s1..sN (each
an ordinary clemcore results folder), written by `sartco report -r RESULTS` as passk.md / .csv.

Per (model, game, experiment), over its episodes (matched by episode folder name across the
sample folders; n = the samples that have a scores.json, c = those with execution success 1):
  pass@k  the unbiased estimator of Chen et al. 2021 (Codex paper), 1 - C(n-c, k) / C(n, k):
          the chance that at least one of k samples drawn without replacement succeeds
  pass^k  C(c, k) / C(n, k): the chance that all k samples succeed
averaged over the episodes, in percent, for k = 1, 5 and N (k > N left out; NaN when an
episode has fewer than k samples, e.g. a sample run that stopped early). pass@1 = pass^1 = the
mean ES of the samples. A deterministic model (mock, rulebased) has c in {0, n} for every
episode, so its pass@k = pass^k = pass@1. A RESULTS folder that holds nothing but samples/ gets
passk.md / .csv alone.
"""
from __future__ import annotations

from collections import defaultdict
from math import comb
from pathlib import Path

from sartco.clem.tooling.sampling import SAMPLES  # RESULTS/samples/s1..sN

from .files import markdown_table, write_csv
from .rows import collect


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


def counts(per_sample: list[list[dict]]) -> dict[tuple, dict[str, list[int]]]:
    """(model, game, experiment) -> episode -> [n, c] from the episodes of each sample folder."""
    out: dict[tuple, dict[str, list[int]]] = defaultdict(lambda: defaultdict(lambda: [0, 0]))
    for episodes in per_sample:
        for e in episodes:
            nc = out[(e["model"], e["game"], e["experiment"])][e["episode"]]
            nc[0] += 1
            nc[1] += int(e["es"] == 1)
    return out


def rows(table: dict[tuple, dict[str, list[int]]], ks: list[int]) -> list[dict]:
    out = []
    for (model, game, experiment), episodes in sorted(table.items()):
        ncs = list(episodes.values())
        row = {"model": model, "game": game, "experiment": experiment, "episodes": len(ncs),
               "samples": min(n for n, _ in ncs)}
        for k in ks:
            row[f"pass@{k}"] = round(100 * sum(pass_at_k(n, c, k) for n, c in ncs) / len(ncs), 2)
            row[f"pass^{k}"] = round(100 * sum(pass_all_k(n, c, k) for n, c in ncs) / len(ncs), 2)
        out.append(row)
    return out


def samples_only(results: Path) -> bool:
    """RESULTS holds sample folders and no other run."""
    return bool(sample_folders(results)) and not any(p.is_dir() and p.name != SAMPLES for p in results.iterdir())


def write_alone(results: Path, out: Path) -> int:
    """`sartco report` of a folder with nothing but samples: passk.md / .csv."""
    out.mkdir(parents=True, exist_ok=True)
    print("sartco report: samples only -> " + ", ".join(str(out / w) for w in write(results, out)))
    return 0


def write(results: Path, out: Path) -> list[str]:
    """passk.md / passk.csv when RESULTS holds sample folders; the names written."""
    folders = sample_folders(results)
    if not folders:
        return []
    per_sample = [collect(folder) for folder in folders]
    ks = sorted(k for k in {1, 5, len(folders)} if k <= len(folders))
    table = rows(counts(per_sample), ks)
    header = ["model", "game", "experiment", "episodes", "samples"] + [f"{p}{k}" for k in ks for p in ("pass@", "pass^")]
    write_csv(out / "passk.csv", header, table)
    md = (f"# pass@k over {len(folders)} samples per episode ({results / SAMPLES})\n\n"
          "pass@k = chance that at least one of k samples succeeds (execution success; unbiased estimator of "
          "Chen et al. 2021), pass^k = chance that all k succeed, in % over the episodes; NaN when an episode has "
          "fewer than k samples.\n\n")
    (out / "passk.md").write_text(md + markdown_table(header, [[r[h] for h in header] for r in table]), encoding="utf-8")
    return ["passk.md", "passk.csv"]
