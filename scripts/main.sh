#!/usr/bin/env bash
# The main job (`make main`): both games with the built-in players over the test split, scored,
# transcribed, evaluated and reported; ends by printing the results table. Each game is played by
# each of MODELS, side by side in the tables: `mock` (the gold code: the harness's ceiling) and
# `rulebased` (the rule-based follower, the honest non-LLM baseline: 100 % on template
# instructions, a few % on human- and model-written ones).
#   cobot_instruct  mock (gold code) on the template cells of Table 3 (generated dataset v1) and
#                   on the human- and model-written cells (imported published data), plus the
#                   val-split ablations that ship in in/instances.json; the feedback experiments
#   cobot_describe  mock describer (template instructions) + mock builder (the rule-based follower)
# Settings (environment): RESULTS (results), MODELS ("mock rulebased"), SCORES (scores).
set -euo pipefail
cd "$(dirname "$0")/.."
RESULTS="${RESULTS:-results}"
MODELS="${MODELS:-${MODEL:-mock rulebased}}"
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

for MODEL in $MODELS; do
step "cobot_instruct ($MODEL): template cells and ablations (in/instances.json)"
run clem run -g cobot_instruct -m "$MODEL" -r "$RESULTS"
step "cobot_instruct ($MODEL): human- and model-written cells (in/instances_published.json)"
run clem run -g cobot_instruct -m "$MODEL" -i instances_published -r "$RESULTS"
step "cobot_instruct ($MODEL): execution feedback and repair, beyond the paper (in/instances_feedback.json)"
run clem run -g cobot_instruct -m "$MODEL" -i instances_feedback -r "$RESULTS"
step "cobot_describe ($MODEL)"
run clem run -g cobot_describe -m "$MODEL" -r "$RESULTS"
done

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
