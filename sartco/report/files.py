"""What every report table shares: reading a results file, a score as a number, and writing a
table as CSV or Markdown."""
from __future__ import annotations

import csv
import json
import math
from pathlib import Path

from sartco.errors import UserError


def number(value) -> float | None:
    """A score as a float; None for a missing, textual or NaN score."""
    if value is None or isinstance(value, str):
        return None
    value = float(value)
    return None if math.isnan(value) else value


def mean(values, *, pct: bool = False, zero: bool = False) -> float:
    """Mean (x 100 when pct), rounded to 2 places; missing values (None) count 0 when zero, else
    are left out; NaN when nothing is left."""
    values = [0.0 if v is None else v for v in values] if zero else [v for v in values if v is not None]
    if not values:
        return float("nan")
    return round((100.0 if pct else 1.0) * sum(values) / len(values), 2)


def percent(values) -> float:
    """Mean in percent over all values; a missing value (an aborted episode) counts 0."""
    return mean(values, pct=True, zero=True)


def load_json(path: Path) -> dict:
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError) as exc:
        raise UserError(f"{path}: cannot read JSON ({exc})") from None


def write_csv(path: Path, header: list[str], rows: list[dict]) -> None:
    with path.open("w", newline="", encoding="utf-8") as f:
        writer = csv.DictWriter(f, fieldnames=header, lineterminator="\n")
        writer.writeheader()
        writer.writerows(rows)


def markdown_table(header: list[str], rows: list[list]) -> str:
    out = ["| " + " | ".join(header) + " |", "|" + "|".join("---" for _ in header) + "|"]
    out += ["| " + " | ".join("" if v is None else f"{v:.2f}" if isinstance(v, float) else str(v) for v in r) + " |"
            for r in rows]
    return "\n".join(out) + "\n"


MANIFEST = ".report-files"  # the names the last `sartco report` wrote into its --out folder


def replace_stale(out: Path, written: list[str]) -> list[str]:
    """Remove the files an earlier report wrote into `out` that this one did not (only names of
    the earlier report's manifest: nothing else in the folder is touched), record this report's
    names; the names removed."""
    manifest = out / MANIFEST
    earlier = manifest.read_text(encoding="utf-8").split("\n") if manifest.is_file() else []
    stale = [n for n in earlier if n and n not in written and "/" not in n and (out / n).is_file()]
    for name in stale:
        (out / name).unlink()
    manifest.write_text("".join(f"{n}\n" for n in written), encoding="utf-8")
    return stale
