"""`make lint`'s type check: mypy over sartco/ (pyproject.toml [tool.mypy]: strict on settings,
the base layer, world and program) against scripts/mypy-baseline.txt.

The baseline lists, per file, the errors mypy reports there today ("path count"); a file not
listed must have none. The check fails (exit 1) when a file has more errors than its count, and
also when it has fewer (a fixed error is not room for a new one): `python scripts/typecheck.py
--update` then writes the smaller counts. The counts only shrink: --update refuses while any file
has more than its count (without a baseline file it writes today's counts).

    python scripts/typecheck.py            # the check (make lint)
    python scripts/typecheck.py --update   # write the counts that went down
"""
from __future__ import annotations

import argparse
import re
import subprocess
import sys
from collections import Counter
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
BASELINE = ROOT / "scripts" / "mypy-baseline.txt"
ERROR = re.compile(r"^(?P<path>[\w./-]+\.py):\d+: error: ")


def errors_per_file(output: str) -> Counter[str]:
    """path -> number of errors, from mypy's output."""
    return Counter(m["path"] for line in output.splitlines() if (m := ERROR.match(line)))


def read_baseline(path: Path = BASELINE) -> dict[str, int]:
    counts = {}
    for n, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
        if line.strip() and not line.startswith("#"):
            try:
                name, count = line.split()
                counts[name] = int(count)
            except ValueError:
                raise SystemExit(f"{path}:{n}: expected 'path count', got {line!r}") from None
    return counts


def compare(found: Counter[str], baseline: dict[str, int]) -> tuple[list[str], list[str]]:
    """(files over their count, files under it), each as a line for the user."""
    over = [f"{name}: {found[name]} errors, baseline {baseline.get(name, 0)}"
            for name in sorted(found) if found[name] > baseline.get(name, 0)]
    under = [f"{name}: {found.get(name, 0)} errors, baseline {count}"
             for name, count in sorted(baseline.items()) if found.get(name, 0) < count]
    return over, under


def write_baseline(found: Counter[str], path: Path = BASELINE) -> None:
    lines = ["# mypy errors per file (scripts/typecheck.py): counts only shrink; a file not listed has none"]
    path.write_text("\n".join(lines + [f"{name} {found[name]}" for name in sorted(found)]) + "\n", encoding="utf-8")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--update", action="store_true", help="write the counts that went down")
    args = parser.parse_args(argv)
    done = subprocess.run([sys.executable, "-m", "mypy"], cwd=ROOT, capture_output=True, text=True)
    if done.returncode not in (0, 1) or "error: " not in done.stdout and done.returncode:
        print(done.stdout + done.stderr, file=sys.stderr)
        return 2  # mypy itself failed (a bad config, a crash)
    found = errors_per_file(done.stdout)
    if args.update and not BASELINE.exists():  # the first baseline: today's counts
        write_baseline(found)
        print(f"mypy: {sum(found.values())} errors in {len(found)} files written to scripts/mypy-baseline.txt")
        return 0
    over, under = compare(found, read_baseline())
    if over:
        print("mypy: more errors than scripts/mypy-baseline.txt allows:\n  " + "\n  ".join(over), file=sys.stderr)
        print("\n".join(line for line in done.stdout.splitlines()
                        if (m := ERROR.match(line)) and any(o.startswith(m["path"] + ":") for o in over)), file=sys.stderr)
        return 1
    if args.update:
        write_baseline(found)
    elif under:  # the baseline shrinks with the code: a fixed error is not room for a new one
        print("mypy: fewer errors than scripts/mypy-baseline.txt lists; write the new counts with "
              "python scripts/typecheck.py --update:\n  " + "\n  ".join(under), file=sys.stderr)
        return 1
    print(f"mypy: {sum(found.values())} errors in {len(found)} files, none beyond scripts/mypy-baseline.txt")
    return 0


if __name__ == "__main__":
    sys.exit(main())
