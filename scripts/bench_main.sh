#!/usr/bin/env bash
# The cost of `make main` in one checkout against another, measured in the same command, and
# whether their results are the same: both run scripts/main.sh (each with its own .venv, `make
# install` first, not timed) into a temporary results folder, one after the other (the wall
# times are comparable; PARALLEL=1 runs them side by side, then compare CPU only). Prints:
# - per step, the wall and CPU seconds (user + sys, children included: the sandbox's processes)
#   of each checkout: every clem / sartco / python command main.sh starts (timed by
#   /usr/bin/time), and the tasks `sartco suite` reports, when main.sh runs it;
# - the whole of main.sh in each: wall and CPU, and new / base;
# - scripts/compare_results.py on the two results and tables folders (exit 1 when a result differs).
#   usage: scripts/bench_main.sh BASE_CHECKOUT NEW_CHECKOUT
#   e.g. git worktree add /tmp/base 2b0163b; scripts/bench_main.sh /tmp/base .
set -euo pipefail
[ $# -eq 2 ] || { echo "usage: $0 BASE_CHECKOUT NEW_CHECKOUT" >&2; exit 2; }
command -v /usr/bin/time >/dev/null || { echo "$0 needs /usr/bin/time (Debian package 'time')" >&2; exit 2; }
HERE="$(cd "$(dirname "$0")" && pwd)"
OUT="$(mktemp -d)"
echo "bench: results and timings under $OUT"

bench() {  # bench NAME CHECKOUT: make main's steps in CHECKOUT, each command's CPU in $OUT/NAME.times
  local name="$1" dir shim
  dir="$(cd "$2" && pwd)"
  shim="$OUT/$name.bin"
  mkdir -p "$shim"
  make -C "$dir" install >/dev/null
  for cmd in clem sartco python; do
    printf '#!/bin/sh\nexec /usr/bin/time -a -o %s -f "%%e %%U %%S %s %%C" %s/.venv/bin/%s "$@"\n' \
      "$OUT/$name.times" "$cmd" "$dir" "$cmd" > "$shim/$cmd"
    chmod +x "$shim/$cmd"
  done
  (cd "$dir" && PATH="$shim:$dir/.venv/bin:$PATH" RESULTS="$OUT/$name.results" SCORES="$OUT/$name.scores" \
    /usr/bin/time -o "$OUT/$name.total" -f "%e %U %S" bash scripts/main.sh > "$OUT/$name.out" 2>&1) \
    || { echo "bench: make main failed in $dir ($OUT/$name.out)" >&2; return 1; }
}

if [ "${PARALLEL:-0}" = 1 ]; then
  bench base "$1" & b=$!
  bench new "$2" & n=$!
  wait $b; wait $n
else
  bench base "$1"; bench new "$2"
fi

python3 - "$OUT" <<'EOF'
import re, sys
from pathlib import Path

out = Path(sys.argv[1])

def steps(name):
    """(step, wall, cpu) of each command main.sh started, and of each task sartco suite reported."""
    rows = []
    for line in (out / f"{name}.times").read_text().splitlines():
        parts = line.split(None, 4)
        if len(parts) < 5 or not re.match(r"^[\d.]+$", parts[0]):
            continue   # /usr/bin/time's "Command exited with non-zero status" lines
        wall, user, sys_, cmd, command = parts
        args = [w for w in command.split()[1:] if not w.startswith("/")]
        rows.append((f"{cmd} {' '.join(args)}"[:64], float(wall), float(user) + float(sys_)))
    for m in re.finditer(r"^== (.+?): (?:done|FAILED|exit \d+) in ([\d.]+) s \(([\d.]+) s CPU\)",
                         (out / f"{name}.out").read_text(), re.M):
        rows.append(("  suite: " + m.group(1)[:56], float(m.group(2)), float(m.group(3))))
    return rows

def total(name):
    wall, user, sys_ = (out / f"{name}.total").read_text().split()[-3:]
    return float(wall), float(user) + float(sys_)

for name in ("base", "new"):
    print(f"\n{name}: {'step':64s} {'wall s':>8s} {'CPU s':>8s}")
    for step, wall, cpu in steps(name):
        print(f"{'':6s}{step:64s} {wall:8.1f} {cpu:8.1f}")
(bw, bc), (nw, nc) = total("base"), total("new")
print(f"\n{'make main (scripts/main.sh), install apart':58s} {'base':>9s} {'new':>9s} {'new/base':>9s}")
print(f"{'wall s':58s} {bw:9.1f} {nw:9.1f} {nw / bw:9.3f}")
print(f"{'CPU s (user + sys, children included)':58s} {bc:9.1f} {nc:9.1f} {nc / bc:9.3f}")
EOF
echo
python3 "$HERE/compare_results.py" "$OUT/base.results" "$OUT/new.results" "$OUT/base.scores" "$OUT/new.scores" \
  --checkouts "$(cd "$1" && pwd)" "$(cd "$2" && pwd)"
