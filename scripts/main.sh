#!/usr/bin/env bash
# The main job (`make main`): both games with the built-in players over the test split, scored,
# transcribed, evaluated and reported; ends by printing the results table.
#   cobot_instruct  mock (gold code) on the template cells of Table 3 (generated dataset v1) and
#                   on the human- and model-written cells (imported published data), plus the
#                   val-split ablations that ship in in/instances.json; the feedback experiments
#   cobot_describe  mock describer (template instructions, answers, corrections) + mock builder (the
#                   rule-based follower), in the modes oneshot, clarify, correct, clarify_correct
# Settings (environment): RESULTS (results), MODEL (mock), SCORES (scores).
set -euo pipefail
cd "$(dirname "$0")/.."
RESULTS="${RESULTS:-results}"
MODEL="${MODEL:-mock}"
SCORES="${SCORES:-scores}"
SHARED="../shared/sartco-data/published"
test -d "$SHARED" || { echo "make main needs the published SARTCo data at $SHARED" >&2; exit 2; }

mkdir -p "$RESULTS"
LOG="$RESULTS/main.log"   # clemcore's progress bars and logs go here; the terminal gets the steps
: > "$LOG"
step() { printf '== %s\n' "$*"; }
run() {
  "$@" >> "$LOG" 2>&1 || { tail -25 "$LOG"; echo "make main: failed: $*  (full log: $LOG)" >&2; exit 1; }
}

step "importing the published SARTCo data (derived from ../shared, not committed)"
run sartco import "$SHARED" --out instances/published --quiet
run python games/cobot_instruct/instancegenerator.py --published instances/published

step "cobot_instruct: template cells and ablations (in/instances.json)"
run clem run -g cobot_instruct -m "$MODEL" -r "$RESULTS"
step "cobot_instruct: human- and model-written cells (in/instances_published.json)"
run clem run -g cobot_instruct -m "$MODEL" -i instances_published -r "$RESULTS"
step "cobot_instruct: execution feedback and repair, beyond the paper (in/instances_feedback.json)"
run clem run -g cobot_instruct -m "$MODEL" -i instances_feedback -r "$RESULTS"
step "cobot_describe"
run clem run -g cobot_describe -m "$MODEL" -r "$RESULTS"

step "scoring, transcribing, evaluating"
run clem score -r "$RESULTS"
run clem transcribe -r "$RESULTS"
run clem eval -r "$RESULTS"
run sartco report -r "$RESULTS" --out "$SCORES"

step "results: $RESULTS/ (transcripts, results.csv, main.log), tables in $SCORES/"
echo
cat "$SCORES/table3.md"
echo
cat "$SCORES/repair.md"
