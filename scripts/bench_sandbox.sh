#!/usr/bin/env bash
# `sartco bench-execute` of another checkout (BASE, e.g. a worktree of 2b0163b: reused workers)
# and of this one (a fresh confined process per program), alternating, in one run on one machine:
#   git worktree add /tmp/base 2b0163b; scripts/bench_sandbox.sh /tmp/base [ROUNDS] [REPEAT]
# Both run with this checkout's .venv python; each side imports its own sartco (PYTHONPATH).
set -euo pipefail
BASE=${1:?usage: scripts/bench_sandbox.sh BASE_CHECKOUT [ROUNDS] [REPEAT]}
ROUNDS=${2:-2}
REPEAT=${3:-3}
HERE=$(cd "$(dirname "$0")/.." && pwd)
PY=${PYTHON:-$HERE/.venv/bin/python}
DATA=${SARTCO_DATA:-$HERE/../shared/sartco-data}
for round in $(seq "$ROUNDS"); do
  for side in "$BASE" "$HERE"; do
    echo "== round $round: $(git -C "$side" log -1 --format='%h %s' | cut -c1-70) ($(uptime | sed 's/.*load/load/'))"
    (cd "$side" && PYTHONPATH="$side" "$PY" -c "import sys; from sartco.cli import main; sys.exit(main())" \
      bench-execute --data "$DATA" --repeat "$REPEAT" | grep -E "headline|floor:|execute distinct|cold,|compile\(\), all")  # old and new lines
  done
done
