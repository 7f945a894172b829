#!/usr/bin/env bash
# The main job (`make main`): both games with the built-in players over the test split, scored,
# transcribed, evaluated and reported; ends by printing the results tables. Each kind of run is
# played under its own game name (games/cobot_instruct/clemgame.json), so that clem eval scores it
# apart, and the test cells by each of MODELS side by side: `mock` (the gold code: the harness's
# ceiling) and `rulebased` (the rule-based follower, the honest non-LLM baseline: 100 % on template
# instructions, a few % on human- and model-written ones).
#   cobot_instruct            the template cells of Table 3 (generated dataset v1), every model
#   cobot_instruct_published  the human- and model-written cells (imported published data), every model
#   cobot_describe            describer + builder (mock: template instructions + the rule-based
#                             follower), the paper's one-shot mode alone, every model
#   cobot_describe_dialogue   the same in the dialogue modes clarify, correct, clarify_correct
#                             (answers, corrections), every model
#   cobot_instruct_paper      the paper protocol on the published test files (in/instances_paper.json),
#                             with the paper's settings (-t 0 -l 250): mock only (the authors' gold answers;
#                             the rule-based follower does not write the authors' answer format)
#   cobot_instruct_ablations, cobot_instruct_feedback   val-split ablations, execution feedback and
#                             repair: mock only (rulebased repeats its template numbers there)
#   cobot_instruct_feedback, cobot_describe_dialogue   also by `erring` (sartco.clem.players.erring: the
#                             rule-based players with seeded mistakes, p = 0.3, seed 42), whose
#                             repairs, questions and corrections give the repair and dialogue tables
#                             real recovery curves (about 4 min: play 1, score+transcribe 1, eval 2)
# Settings (environment): RESULTS (results), MODELS ("mock rulebased"), ERRING ("erring"; "" skips
# it), SCORES (scores), SARTCO_DATA (the SARTCo data folder; ../shared/sartco-data).
set -euo pipefail
cd "$(dirname "$0")/.."
RESULTS="${RESULTS:-results}"
MODELS="${MODELS:-mock rulebased}"
ERRING="${ERRING-erring}"
SCORES="${SCORES:-scores}"
SHARED="${SARTCO_DATA:-../shared/sartco-data}/published"   # the data folder: sartco.settings
test -d "$SHARED" || { echo "make main needs the published SARTCo data at $SHARED (set SARTCO_DATA to the data folder)" >&2; exit 2; }

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
run python games/cobot_instruct/instancegenerator.py --protocol paper

FIRST="${MODELS%% *}"
PLAYED=()
play() {  # play GAME MODEL [clem run options...]
  local game="$1" model="$2"; shift 2
  step "$game ($model)"
  run clem run -g "$game" -m "$model" -r "$RESULTS" "$@"
  PLAYED+=("$game $model")
}
for MODEL in $MODELS; do
  play cobot_instruct "$MODEL"
  play cobot_instruct_published "$MODEL"
  play cobot_describe "$MODEL"
  play cobot_describe_dialogue "$MODEL"
done
# fresh boards (issue 24 item 3, sartco.clem.instruct.fresh): cobot_instruct_fresh, the published test boards beside as
# many fresh boards of FRESH_SEED (same strata; in no published and no seed-42 file: the overlap count printed),
# template instructions, every model: contamination.md; with cobot_instruct_published: robustness.md
FRESH_SEED="${FRESH_SEED:-7}"
step "fresh boards (seed $FRESH_SEED)"
run python games/cobot_instruct/instancegenerator.py --fresh "$FRESH_SEED"
grep "^fresh boards" "$LOG" | tail -1   # how many, and the overlap with the published and seed-42 boards (0)
for MODEL in $MODELS; do play cobot_instruct_fresh "$MODEL"; done
play cobot_instruct_paper "$FIRST" -t 0 -l 250
play cobot_instruct_ablations "$FIRST"
play cobot_instruct_feedback "$FIRST"
for MODEL in $ERRING; do
  play cobot_instruct_feedback "$MODEL"
  play cobot_describe_dialogue "$MODEL"
done

step "scoring, transcribing, evaluating"
run clem score -r "$RESULTS"
run clem transcribe -r "$RESULTS"
# one game and model at a time: clem eval adds their episodes to raw.csv and recomputes the table;
# clemcore builds the rows of what it loads one by one (the cost grows with the square of their
# number), so a single eval over everything takes many times longer (44 min instead of minutes)
rm -f "$RESULTS/raw.csv"
for pair in "${PLAYED[@]}"; do set -- $pair; run clem eval -r "$RESULTS" -g "$1" -m "$2"; done
# stops (exit 3) when an episode of an instance file is missing, errored, unscored or unreadable:
# the ids are in the log's last lines and $SCORES/completeness.md; `sartco resume` completes the run
# sartco report exits 3 when any episode is a harness error (the harness failed, not the model;
# harness.md names them): then make main fails here, with the report's line at the end of the log
run sartco report -r "$RESULTS" --out "$SCORES"

step "results: $RESULTS/ (transcripts, results.csv, main.log), tables in $SCORES/"
echo
cat "$SCORES/paper_table3.md"   # the paper protocol beside the paper's figures, then ours (table3.md)
echo
cat "$SCORES/repair.md"
echo
# the dialogue modes' recovery curves (ES after round k; the whole table and the plot: dialogue.md)
echo "# cobot_describe as a dialogue"; echo
sed -n '/^## ES after round k/,/^## Per experiment/p' "$SCORES/dialogue.md" | sed '$d'
cat "$SCORES/contamination.md"; echo; cat "$SCORES/robustness.md"; echo   # issue 24 items 3-4
echo "report (tables, charts, example transcripts; open in a browser): $SCORES/report.html"
