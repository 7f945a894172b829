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

# everything below in one command on every core: sartco suite (sartco/suite.py) runs what these
# steps did one after another (sartco import, instancegenerator.py --published / --protocol paper /
# --fresh, clem run per game and model, clem score, clem transcribe, clem eval per pair, sartco
# report) through clemcore's own API in one process per core, and writes the same files
mkdir -p "$RESULTS"
LOG="$RESULTS/main.log"   # clemcore's progress bars and logs go here; the terminal gets the steps
FRESH_SEED="${FRESH_SEED:-7}"
# stops (exit 3) when an episode of an instance file is missing, errored, unscored or unreadable
# (the ids: $SCORES/completeness.md; `sartco resume` completes the run), or is a harness error
# (the harness failed, not the model: $SCORES/harness.md names them)
sartco suite -r "$RESULTS" --out "$SCORES" -m $MODELS --erring $ERRING --fresh-seed "$FRESH_SEED" \
  || { status=$?; [ $status = 130 ] && exit 130   # Ctrl-C: the suite said what it kept; make main again goes on
       tail -25 "$LOG"; echo "make main: sartco suite failed (exit $status; full log: $LOG)" >&2; exit 1; }

printf "== results: %s/ (transcripts, results.csv, main.log), tables in %s/\n" "$RESULTS" "$SCORES"
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
