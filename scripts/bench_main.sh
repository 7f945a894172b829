#!/usr/bin/env bash
# The cost of `make main` in one checkout against another, measured in the same command: both
# run scripts/main.sh (each with its own .venv, `make install` first) into a temporary results
# folder, every clem / sartco / python command timed (CPU = user + sys, its children included:
# the sandbox's workers); prints per step the CPU seconds of both and their ratio, then the total.
# CPU seconds, not wall time: the machines are shared, and the two runs may go side by side.
#   usage: scripts/bench_main.sh BASE_CHECKOUT NEW_CHECKOUT     (PARALLEL=0: one after the other)
#   e.g. git worktree add /tmp/base <commit>; scripts/bench_main.sh /tmp/base .
set -euo pipefail
[ $# -eq 2 ] || { echo "usage: $0 BASE_CHECKOUT NEW_CHECKOUT" >&2; exit 2; }
command -v /usr/bin/time >/dev/null || { echo "$0 needs /usr/bin/time (Debian package 'time')" >&2; exit 2; }
OUT="$(mktemp -d)"
echo "bench: results and timings under $OUT"

bench() {  # bench NAME CHECKOUT: make main's steps in CHECKOUT, each command's CPU in $OUT/NAME.times
  local name="$1" dir shim
  dir="$(cd "$2" && pwd)"
  shim="$OUT/$name.bin"
  mkdir -p "$shim"
  make -C "$dir" install >/dev/null
  for cmd in clem sartco python; do
    printf '#!/bin/sh\nexec /usr/bin/time -a -o %s -f "%%U %%S %s %%C" %s/.venv/bin/%s "$@"\n' \
      "$OUT/$name.times" "$cmd" "$dir" "$cmd" > "$shim/$cmd"
    chmod +x "$shim/$cmd"
  done
  (cd "$dir" && PATH="$shim:$dir/.venv/bin:$PATH" RESULTS="$OUT/$name.results" SCORES="$OUT/$name.scores" \
    bash scripts/main.sh > "$OUT/$name.out" 2>&1) || { echo "bench: make main failed in $dir ($OUT/$name.out)" >&2; return 1; }
}

if [ "${PARALLEL:-1}" = 1 ]; then
  bench base "$1" & b=$!
  bench new "$2" & n=$!
  wait $b; wait $n
else
  bench base "$1"; bench new "$2"
fi

# a step: the command with its results folder and the checkout's own paths taken out
python3 - "$OUT/base.times" "$OUT/new.times" <<'EOF'
import re, sys

def load(path):
    steps = {}
    for line in open(path):
        parts = line.split(None, 3)
        if len(parts) < 4 or not re.match(r"^[\d.]+$", parts[0]):
            continue   # /usr/bin/time's "Command exited with non-zero status" lines
        user, sys_, name, command = parts
        words = command.split()[1:]
        args = [w for w in words if not w.startswith("/")]
        key = name + " " + " ".join(args)
        key = key[:70]
        steps[key] = steps.get(key, 0.0) + float(user) + float(sys_)
    return steps

base, new = load(sys.argv[1]), load(sys.argv[2])
print(f"{'step':70s} {'base s':>8s} {'new s':>8s} {'ratio':>6s}")
for key in list(dict.fromkeys([*base, *new])):
    b, n = base.get(key, 0.0), new.get(key, 0.0)
    print(f"{key:70s} {b:8.1f} {n:8.1f} {n / b if b else float('nan'):6.2f}")
tb, tn = sum(base.values()), sum(new.values())
print(f"{'total CPU (user + sys)':70s} {tb:8.1f} {tn:8.1f} {tn / tb:6.3f}")
EOF
