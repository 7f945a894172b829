"""How often the sandbox builds what plain `exec` builds, on the honest-program corpus.

    python tools/honest_corpus.py [--corpus tests/program/corpus] [--semantics module|paper] [--json OUT]

Corpus: every `NNN_name.py` of tests/program/corpus, programs of the kinds models write for the
task (straight puts, loops, helpers, classes, generators, numpy coordinates, seeded random, ...),
each correct and inside the task's world; some end in a world error on purpose.

The oracle: plain `exec` of the program, with the real builtins and modules, in one namespace
holding the authors' names (`board` = a fresh 8x8 sartco.world Board, `put`, `init_board`, `np` =
real numpy) and `__name__ == "__main__"` (our protocol runs a program as a script runs it), in a
child process with a fixed string hash seed (HASH_SEED; the sandbox's workers fix theirs too), so
that set iteration is reproducible. The board that counts is the global `board` if it is a Board,
else the most recently created one (the sandbox's rule). Outcome: "ok" or the WorldError's code;
any other exception means the program is not honest, a fault of the corpus (reported apart).
With `--semantics paper` the oracle is the authors' scorer's `exec(code, globals, locals)`
(namespaces.py: the scorer's globals, `board` and `instruction` as locals, `__name__` not
"__main__"); there a Python error is an outcome too (the paper's scoping errors: a function that
reads a top-level name is a NameError under plain exec as in the sandbox), named by the sandbox's
error code (runtime.classify).

The sandbox: sartco.program.execute_many (our protocol). A program agrees when both give the same
outcome (ok, or the same world error code) and exactly the same cells. Prints the agreement
("316/321 = 0.984") and each disagreement with both sides; `known_disagreements.json` (name ->
reason) of the corpus folder is shown beside it. Exit status 0 (a report, not a check: the test
tests/program/test_honest.py holds the thresholds).
"""
from __future__ import annotations

import argparse
import contextlib
import io
import json
import os
import subprocess
import sys
import types
from dataclasses import asdict, dataclass
from pathlib import Path

from sartco.program import MODULE, PAPER, execute_many
from sartco.program.execution import SEMANTICS

REPO = Path(__file__).resolve().parents[1]
CORPUS = REPO / "tests" / "program" / "corpus"
KNOWN = "known_disagreements.json"
HASH_SEED = "0"
OK = "ok"


def load(corpus: Path = CORPUS) -> list[tuple[str, str]]:
    """(name, source) of every program of the corpus, in name order."""
    return [(p.stem, p.read_text(encoding="utf-8")) for p in sorted(corpus.glob("[0-9]*.py"))]


def known(corpus: Path = CORPUS) -> dict[str, str]:
    """The listed disagreements: program name -> one-line reason."""
    path = corpus / KNOWN
    return json.loads(path.read_text(encoding="utf-8")) if path.exists() else {}


# --- the oracle: plain exec (runs in a child process, see oracle()) -------------------------------

def _plain_exec(source: str, semantics: str = MODULE) -> list:
    """[outcome, cells] of plain exec under the authors' namespace (outcome "ok", a world error
    code, or "not honest: ..." for any other exception; under PAPER that exception's code)."""
    import collections
    import copy

    import numpy  # the real one, as the authors' scorer module had it

    from sartco.program.child import namespaces
    from sartco.program.child.runtime import classify
    from sartco.world import Board, WorldError, put

    last = [Board(8, 8)]

    def init_board(rows=8, cols=8):
        last[0] = Board(rows, cols)
        return last[0]

    passed = last[0]
    env = {"__name__": "__main__", "board": passed, "put": put, "init_board": init_board, "np": numpy}
    if semantics == MODULE:  # the program is the script: `__main__` (dataclasses reads string annotations there)
        sys.modules["__main__"] = script = types.SimpleNamespace()  # type: ignore[assignment]
        script.__dict__.update(env)
        env = script.__dict__
    scope = env
    if semantics == PAPER:  # the authors' exec(code) inside a function of their scorer module
        env = {"__name__": namespaces.MODULE_NAME, "put": put, "init_board": init_board, "np": numpy,
               "json": json, "re": __import__("re"), "Counter": collections.Counter, "deepcopy": copy.deepcopy}
        scope = {"instruction": source, "board": passed}
    try:
        with contextlib.redirect_stdout(io.StringIO()):
            exec(compile(source, "<honest>", "exec", dont_inherit=True), env, scope)
        outcome = OK
    except WorldError as exc:
        outcome = exc.code.value
    except Exception as exc:  # the corpus's own fault, reported as such (a paper scoping error is not)
        outcome = classify(exc).value if semantics == PAPER else f"not honest: plain exec raised {type(exc).__name__}: {exc}"
    result = passed if semantics == PAPER else env.get("board")  # PAPER: the board passed in is scored
    return [outcome, (result if type(result) is Board else last[0]).cells()]


def oracle(sources: list[str], hash_seed: str = HASH_SEED, semantics: str = MODULE) -> list[list]:
    """[outcome, cells] per program, from one child process with PYTHONHASHSEED=hash_seed."""
    env = {**os.environ, "PYTHONHASHSEED": hash_seed}
    child = subprocess.run([sys.executable, __file__, "--oracle", "--semantics", semantics], input=json.dumps(sources), env=env,
                           capture_output=True, text=True, check=False)
    if child.returncode:
        raise RuntimeError(f"the oracle process failed: {child.stderr.strip()[-2000:]}")
    return json.loads(child.stdout)


# --- the comparison -----------------------------------------------------------------------------

@dataclass
class Result:
    name: str
    agrees: bool
    plain: str  # the oracle's outcome
    sandbox: str  # the sandbox's outcome ("ok", or "code: message")
    detail: str  # what differs, "" when they agree
    pieces: int  # how many pieces plain exec left on the board

    @property
    def honest(self) -> bool:
        return not self.plain.startswith("not honest")


def _differences(plain: dict, sandbox: dict, most: int = 3) -> str:
    """The first cells whose stacks differ, both sides."""
    keys = [k for k in {**plain, **sandbox} if plain.get(k) != sandbox.get(k)]
    shown = "; ".join(f"{k} plain exec {plain.get(k, [])} sandbox {sandbox.get(k, [])}" for k in keys[:most])
    return shown + (f"; and {len(keys) - most} more cells" if len(keys) > most else "")


def run(programs: list[tuple[str, str]], semantics: str = MODULE) -> list[Result]:
    """Each program through the oracle and the sandbox, compared."""
    sources = [source for _, source in programs]
    expected = oracle(sources, semantics=semantics)
    got = execute_many(sources, semantics=semantics)
    results = []
    for (name, _), (plain, cells), ex in zip(programs, expected, got):
        sandbox = OK if ex.ok else f"{ex.error.value}: {ex.message}"
        same_outcome = (ex.ok and plain == OK) or (not ex.ok and ex.error.value == plain)
        if not same_outcome:
            detail = f"plain exec {plain}, sandbox {sandbox}"
        elif ex.cells != cells:
            detail = f"other board: {_differences(cells, ex.cells)}"
        else:
            detail = ""
        pieces = sum(len(stack) for stack in cells.values())
        results.append(Result(name, not detail, plain, sandbox, detail, pieces))
    return results


def agreement(results: list[Result]) -> str:
    agree = sum(r.agrees for r in results)
    return f"{agree}/{len(results)} = {agree / max(1, len(results)):.3f}"


def report(results: list[Result], listed: dict[str, str]) -> str:
    lines = [f"honest corpus: {agreement(results)} programs build the same board as plain exec"]
    for r in results:
        if not r.honest:
            lines.append(f"  NOT HONEST {r.name}: {r.plain}")
        elif not r.agrees:
            reason = listed.get(r.name, "NOT LISTED in known_disagreements.json")
            lines.append(f"  {r.name}: {r.detail}\n      reason: {reason}")
    stale = sorted(name for name in listed if any(r.name == name and r.agrees for r in results))
    lines += [f"  listed but agrees now: {name}" for name in stale]
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--oracle", action="store_true", help=argparse.SUPPRESS)  # the child's side
    parser.add_argument("--corpus", type=Path, default=CORPUS)
    parser.add_argument("--semantics", choices=SEMANTICS, default=MODULE)
    parser.add_argument("--json", type=Path, help="also write every result as JSON")
    args = parser.parse_args(argv)
    if args.oracle:
        json.dump([_plain_exec(source, args.semantics) for source in json.load(sys.stdin)], sys.stdout)
        return 0
    results = run(load(args.corpus), args.semantics)
    print(report(results, known(args.corpus)))
    if args.json:
        args.json.write_text(json.dumps([asdict(r) for r in results], indent=1), encoding="utf-8")
    return 0


if __name__ == "__main__":
    sys.exit(main())
