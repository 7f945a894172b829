#!/usr/bin/env bash
# The main job (`make main`): both games with the built-in players over the test split, scored,
# transcribed, evaluated and reported; ends by printing the results table.
#   cobot_instruct  mock (gold code) on the template cells of Table 3 (generated dataset v1) and
#                   on the human- and model-written cells (imported published data), plus the
#                   val-split ablations that ship in in/instances.json; the feedback experiments
#   cobot_describe  mock describer (template instructions) + mock builder (the rule-based follower)
# Settings (environment): RESULTS (results), MODEL (mock), SCORES (scores).
set -euo pipefail
cd "$(dirname "$0")/.."
RESULTS="${RESULTS:-results}"
MODEL="${MODEL:-mock}"
SCORES="${SCORES:-scores}"
SHARED="../shared/sartco-data/published"
test -d "$SHARED" || { echo "make main needs the published SARTCo data at $SHARED" >&2; exit 2; }

step() { printf '\n== %s\n' "$*"; }

step "importing the published SARTCo data (derived from ../shared, not committed)"
sartco import "$SHARED" --out instances/published --quiet
python games/cobot_instruct/instancegenerator.py --published instances/published

step "cobot_instruct: template cells and ablations (in/instances.json)"
clem run -g cobot_instruct -m "$MODEL" -r "$RESULTS"
step "cobot_instruct: human- and model-written cells (in/instances_published.json)"
clem run -g cobot_instruct -m "$MODEL" -i instances_published -r "$RESULTS"
step "cobot_instruct: execution feedback and repair, beyond the paper (in/instances_feedback.json)"
clem run -g cobot_instruct -m "$MODEL" -i instances_feedback -r "$RESULTS"
step "cobot_describe"
clem run -g cobot_describe -m "$MODEL" -r "$RESULTS"

step "scoring, transcribing, evaluating"
clem score -r "$RESULTS"
clem transcribe -r "$RESULTS"
clem eval -r "$RESULTS"
sartco report -r "$RESULTS" --out "$SCORES"

step "results ($RESULTS/, tables in $SCORES/)"
cat "$SCORES/table3.md"
echo
cat "$SCORES/repair.md"
