"""`sartco score-responses`: score raw answers given as JSON lines (see sartco.protocols).

Input line: {"id", "file", "sample", "variant", "responses": [raw answer per turn]}; the id is
enough ("<file>/<sample>/<variant>"), or file + sample + variant without it. Blank lines are
skipped; every other line gets exactly one output line, in input order: the scores, or
{"id"?, "error": reason} (bad JSON, not an object, unknown episode, fields that disagree with
the id, responses that are not a list of strings, more responses than turns). Fewer responses
than turns: the missing ones are empty answers (paper: failed turns; ours: no code, aborted).
"""
from __future__ import annotations

import json
import sys
from pathlib import Path

from sartco.clem.core.errors import HarnessFault
from sartco.games.instruct.paper import check_turns
from sartco.errors import UserError
from sartco.paper.vocabulary import PROTOCOL, published_test_files
from sartco.text import escape

from . import add_common, our_episodes, paper_episodes, write_lines

KEY_FIELDS = ("file", "sample", "variant")


def configure(parser) -> None:
    add_common(parser)
    parser.add_argument("inputs", nargs="*", type=Path, metavar="FILE",
                        help="JSON-lines files of responses ('-' or none: standard input)")


class LineError(ValueError):
    """What is wrong with one input line (becomes its error line, with the id when it is known)."""

    def __init__(self, reason: str, id: str | None = None):
        super().__init__(reason)
        self.id = id


def parse_line(text: str) -> dict:
    """The request of one input line: {"id", "responses", ...} with the id filled in."""
    try:
        item = json.loads(text)
    except ValueError as exc:
        raise LineError(f"not valid JSON ({exc})") from None
    if not isinstance(item, dict):
        raise LineError(f"expected a JSON object, got {type(item).__name__}")
    parts = [item.get(k) for k in KEY_FIELDS]
    composed = "/".join(parts) if all(isinstance(p, str) for p in parts) else None
    eid = item.get("id", composed)
    if not isinstance(eid, str):
        raise LineError('no "id" (or "file", "sample" and "variant") string')
    if composed is not None and composed != eid:
        raise LineError(f'"id" {eid!r} disagrees with file/sample/variant {composed!r}', eid)
    responses = item.get("responses")
    if not isinstance(responses, list) or not all(isinstance(r, str) for r in responses):
        raise LineError('"responses" must be a list of strings, one raw answer per turn', eid)
    return {"id": eid, "responses": [escape(r) for r in responses]}  # escaped as the game master escapes answers


def read_lines(inputs: list[Path]) -> list[tuple[str, str]]:
    """(where, text) of every non-blank input line; where = "<file or stdin>:<line number>".
    Lines end at "\n" only (JSON strings may hold other line separators, such as U+2028)."""
    out = []
    for path in inputs or [Path("-")]:
        if str(path) == "-":
            name, text = "stdin", sys.stdin.read()
        else:
            try:
                name, text = str(path), path.read_text(encoding="utf-8")
            except (OSError, UnicodeDecodeError) as exc:
                raise UserError(f"{path}: cannot read ({exc})") from None
        out.extend((f"{name}:{n}", line) for n, line in enumerate(text.split("\n"), 1) if line.strip())
    return out


# ----------------------------------------------------------------------------- the two scorers

def score_paper(episode: dict, responses: list[str]) -> dict:
    from sartco.paper.scoring import score_dialogue

    score = score_dialogue(responses, episode)
    try:
        check_turns(score)
    except HarnessFault as fault:
        raise LineError(f"harness_error: {fault.reason}") from None
    return {"id": episode["id"], "protocol": PROTOCOL, **{k: episode[k] for k in KEY_FIELDS},
            "cell": episode["cell"], **score.to_json()}


def score_ours(episode: dict, responses: list[str]) -> dict:
    """As cobot_instruct's master and BuildScorer do (one attempt)."""
    from sartco.clem.core.building import build_answers
    from sartco.scores import code_bleu, exact_match
    from sartco.world import ErrorCode

    instance = episode["instance"]
    turns = instance["turns"]
    if len(responses) > len(turns):
        raise LineError(f"{len(responses)} responses for {len(turns)} turn(s)")
    try:
        record = build_answers(instance, responses + [""] * (len(turns) - len(responses)))
    except HarnessFault as fault:  # the sandbox failed, not the answer: no score
        raise LineError(f"harness_error: {fault.reason}") from None
    aborted = record.error == ErrorCode.PARSE_ERROR  # an answer without code: nothing was executed
    gold = instance["gold_code"]
    em = 0 if aborted else int(exact_match(record.builder_code, gold))
    cb = 0.0 if aborted else float(code_bleu(record.builder_code, gold))
    es = int(record.es)
    category = record.category
    return {"id": episode["id"], "protocol": episode["protocol"], **{k: episode[k] for k in KEY_FIELDS},
            "em": em, "cb": cb, "es": es, "f1": record.f1, "precision": record.precision, "recall": record.recall,
            "category": category, "message": record.message, "aborted": aborted,
            "turns": [{"em": bool(em), "cb": cb, "es": bool(es), "category": None if es else category}]}


def needed_files(requests: list) -> set[str]:
    return {r["id"].split("/", 1)[0] for r in requests if isinstance(r, dict)}


def run(args) -> int:
    requests: list[dict | LineError] = []
    for where, text in read_lines(args.inputs):
        try:
            requests.append({**parse_line(text), "where": where})
        except LineError as exc:
            requests.append(LineError(f"{where}: {exc}", exc.id))
    if args.protocol == PROTOCOL:
        known = {f.stem for f in published_test_files()}
        files = sorted(needed_files(requests) & known)
        index = {e["id"]: e for e in paper_episodes(args.data, args.generated, files)} if files else {}
        scorer = score_paper
    else:
        index = {e["id"]: e for e in our_episodes(args.data)}
        scorer = score_ours
    return write_lines(answer_line(request, index, scorer) for request in requests)


def answer_line(request, index: dict, scorer) -> dict:
    if isinstance(request, LineError):
        return {"error": str(request)} if request.id is None else {"id": request.id, "error": str(request)}
    episode = index.get(request["id"])
    if episode is None:
        return {"id": request["id"], "error": f"{request['where']}: unknown episode id {request['id']!r}"}
    try:
        return scorer(episode, request["responses"])
    except ValueError as exc:  # LineError, or score_dialogue's: more responses than turns
        return {"id": request["id"], "error": f"{request['where']}: {exc}"}
