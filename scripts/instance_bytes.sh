#!/usr/bin/env bash
# The instance files the generators write, byte for byte (issue 25 item 5: one instance-generation
# command for both games, behaviour unchanged).
#
#   bash scripts/instance_bytes.sh save  REF    # write every kind of file into REF/<case>/
#   bash scripts/instance_bytes.sh check REF    # write them again and `cmp` each against REF
#
# Each case is one command line of scripts/main.sh, the Makefile or a README (the game scripts'
# flags) plus variants with non-default values; in check mode each case also runs through the
# unified `sartco instances` command. The files land where the games read them (games/*/in/) and are
# copied from there. DESCRIBERS (optional): a `sartco import-instructions` dataset folder for the
# --describers case. Needs instances/published (`sartco import ../shared/sartco-data/published
# --out instances/published`) and ../shared. Run from the repository root with the venv on PATH.
set -euo pipefail
mode="${1:?save|check}"; ref="${2:?reference folder}"
I=games/cobot_instruct/instancegenerator.py
D=games/cobot_describe/instancegenerator.py
VARIANT="--seed 7 --examples 3"

# case | game | files | the scripts' command line | the same through `sartco instances`
CASES=(
  "instruct|cobot_instruct|instances.json instances_ablations.json instances_feedback.json instances_smoke.json|python $I|sartco instances instruct"
  "instruct_variant|cobot_instruct|instances.json instances_ablations.json instances_feedback.json instances_smoke.json|python $I $VARIANT --ablation-episodes 2 --smoke 1 --attempts 4|sartco instances instruct $VARIANT --ablation-episodes 2 --smoke 1 --attempts 4"
  "published|cobot_instruct|instances_published.json instances_published_feedback.json|python $I --published instances/published|sartco instances instruct-published --published instances/published"
  "published_variant|cobot_instruct|instances_published.json instances_published_feedback.json|python $I --published instances/published $VARIANT --attempts 2|sartco instances instruct-published --published instances/published $VARIANT --attempts 2"
  "paper|cobot_instruct|instances_paper.json|python $I --protocol paper|sartco instances instruct-paper"
  "fresh|cobot_instruct|instances_fresh.json|python $I --fresh 7|sartco instances instruct-fresh 7"
  "fresh_variant|cobot_instruct|instances_fresh.json|python $I --fresh 3 --fresh-episodes 4 $VARIANT|sartco instances instruct-fresh 3 --fresh-episodes 4 $VARIANT"
  "train|cobot_instruct|instances_train.json|python $I --train --train-episodes 20|sartco instances instruct-train --train-episodes 20"
  "train_all|cobot_instruct|instances_train.json|python $I --train|sartco instances instruct-train"
  "describe|cobot_describe|instances.json instances_dialogue.json instances_slice.json instances_dialogue_slice.json|python $D --slice 2|sartco instances describe --slice 2"
  "describe_variant|cobot_describe|instances.json instances_dialogue.json instances_slice.json instances_dialogue_slice.json|python $D $VARIANT --questions 1 --corrections 2 --slice 1|sartco instances describe $VARIANT --questions 1 --corrections 2 --slice 1"
)
if [ -n "${DESCRIBERS:-}" ]; then
  CASES+=("describers|cobot_instruct|instances_describers.json|python $I --describers $DESCRIBERS|sartco instances instruct-describers $DESCRIBERS")
fi

failed=0
compare() {  # compare CASE GAME FILES LABEL
  for f in $3; do
    if cmp -s "games/$2/in/$f" "$ref/$1/$f"; then echo "same      $1/$f ($4)"
    else echo "DIFFERENT $1/$f ($4)"; failed=1; fi
  done
}
for entry in "${CASES[@]}"; do
  IFS='|' read -r name game files old new <<< "$entry"
  if [ "$mode" = save ]; then
    $old > /dev/null
    mkdir -p "$ref/$name"
    for f in $files; do cp "games/$game/in/$f" "$ref/$name/$f"; done
    echo "saved $name: $files"
  else
    for cmd in "$old" "$new"; do
      if $cmd > /dev/null; then compare "$name" "$game" "$files" "$cmd"
      else echo "FAILED    $name: $cmd"; failed=1; fi
    done
  fi
done
# leave the committed files as the default command lines write them
python $I > /dev/null && python $D --slice 2 > /dev/null
git diff --quiet -- games/*/in || { echo "committed instance files changed"; failed=1; }
exit $failed
