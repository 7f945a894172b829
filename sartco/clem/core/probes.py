"""Function probes: does the model's function build its object anywhere, in any colours, or only
where the episode's usage line puts it?

After an optimal_function or repetition episode's own build (both games' protocol and the paper
protocol, sartco.clem.core.building.record_build, final build), the function the
answer's usage line or loop calls is run on K fresh boards at K held-out arguments, and each
board is compared with the gold function's board at the same arguments.

The function (`probed_function`, probe_program.py): the first call, in source order, in the answer's top-level
statements (inside loops, ifs and try blocks, never inside a def or class body) of a name that a
top-level `def` of the program (the given code, then the answer; the answer's def wins, as when
the program runs) defines, with `board` as its first argument (or `board=`). The gold function
is found by the same rule in the gold program. A repetition answer that calls the given function
without redefining it probes the given function (`Probe Function` says whose it is).

The probe program (`probe_head`, then `probe_call`, probe_program.py): the given code, the answer
without its usage statements (the top-level statements that call the function), a fresh
`board = init_board(rows, cols)`, then `f(board, [colours], x, y)` - the signature (board,
colors, x, y) every prompt gives. The head is the same for each of an answer's probes and each
of a draw's candidates (the sandbox compiles it once for them).

The arguments (`draw_arguments`): candidates drawn by random.Random(f"{seed}/{board_id}/{task}")
(seed PROBE_SEED): an anchor anywhere on the board and one colour per piece of the object (its
combo name has one letter per piece); a candidate is kept when the gold function builds at it
without error, no piece lies directly on a piece of its colour, and its board differs from the
episode's target (so never the episode's own arguments) and from the kept ones. K (instance
field `probes`, default DEFAULT_PROBES; 0 turns the probes off), the first kept in draw order,
from rounds of CANDIDATES x K candidates (ROUNDS at most). Every program runs in the sandbox
(sartco.clem.core.sandbox.run_many): the gold candidates a round at a time (the harness's own
programs: one confined child per round, `gold=True`), one batch for the K probes of an answer (a
confined child per program); a harness_error raises HarnessFault. A process keeps the draws of the boards it probed
(`gold_draws`): every model's episode on a board, and every game's, compares with the same ones.
A game master starts an episode's draws at its setup on a background thread (`draw_ahead`), so
that they are made while the model's request is out, not while clemcore steps the episodes.

sequence_function episodes are not probed: their gold function (and the prompt's examples)
hard-code the puts and ignore the arguments by the task's design, so there is no general gold
function to compare with; first-order episodes have no function.
"""
from __future__ import annotations

import copy
import json
import os
import random
import threading
from collections import OrderedDict
from dataclasses import dataclass
from functools import partial
from typing import NamedTuple

from sartco import settings
from sartco.episode import PROBES_KEY
from sartco.world import COLORS, SUCCESS_CATEGORY, ErrorCode

from sartco.program import current

from . import ahead
from .errors import HarnessFault
from .probe_program import probe_call, probe_head, probed_call, probed_function

PROBED_TASKS = ("optimal_function", "repetition")
DEFAULT_PROBES = settings.PROBES
PROBE_SEED = 0
CANDIDATES = 2                 # candidates drawn per probe wanted, per round
ROUNDS = 8                     # rounds of candidates at most (about half are kept; under a quarter for tall stacks)
NO_FUNCTION = "no_function"    # a probe's category when the answer calls no function of the program


def probed(instance: dict) -> bool:
    """True for an episode whose function is probed."""
    return instance.get("task") in PROBED_TASKS and int(instance.get("probes", DEFAULT_PROBES)) > 0


def combo_of(instance: dict) -> str:
    """The object's combo name: the episode's combo_name, or the paper sample's 4th part."""
    return instance.get("combo_name") or instance["sample"].split("/")[3]


def _plain_colours(cells: dict) -> bool:
    return all(a[1] != b[1] for stack in cells.values() for a, b in zip(stack, stack[1:]))


def draw_arguments(instance: dict, gold: str, name: str, k: int, seed: int = PROBE_SEED) -> list[tuple[dict, dict]]:
    """Up to k (arguments, gold board) pairs (module doc), the same for a seed on every run:
    rounds of CANDIDATES x k candidates until k are kept (ROUNDS at most), the first k that
    qualify in draw order. A round is one sandbox batch of gold programs (`run_many(gold=True)`:
    one confined child for the round in the local sandbox, sartco.program.child.template's mode "gold")."""
    from .sandbox import run_many

    rows, cols, n = instance["rows"], instance["cols"], len(combo_of(instance))
    rng = random.Random(f"{seed}/{instance['board_id']}/{instance['task']}")
    kept: list[tuple[dict, dict]] = []
    boards = [instance["target"]]
    head = probe_head(gold, name, given_code=instance["given_code"], rows=rows, cols=cols)
    for _ in range(ROUNDS):
        candidates = [{"colors": [rng.choice(COLORS) for _ in range(n)], "x": rng.randrange(rows),
                       "y": rng.randrange(cols)} for _ in range(CANDIDATES * k)]
        runs = run_many([head + probe_call(name, a) for a in candidates], rows, cols, gold=True)
        for args, ex in zip(candidates, runs):
            if ex.error == ErrorCode.HARNESS_ERROR:
                raise HarnessFault(f"sandbox (gold probe): {ex.message}")
            if ex.ok and _plain_colours(ex.cells) and ex.cells not in boards and len(kept) < k:
                kept.append((args, ex.cells))
                boards.append(ex.cells)
        if len(kept) == k:
            break
    return kept


@dataclass(frozen=True, slots=True)
class GoldDraws:
    """What an episode's probes compare with (the same for every answer): the gold function's name
    and the (arguments, gold board) pairs of `draw_arguments`."""
    function: str
    draws: list


# the draws of the boards this process has probed (DRAWS at most), by what decides them: an episode
# of another model, or of another game on the same board, gets them without running the gold again
DRAWS = 20_000
_drawn: OrderedDict[tuple, GoldDraws] = OrderedDict()
_drawn_lock = threading.Lock()


def _draws_key(instance: dict, k: int, seed: int) -> tuple:
    return (instance["gold_code"], instance["given_code"], instance["rows"], instance["cols"], combo_of(instance),
            str(instance["board_id"]), instance["task"], json.dumps(instance["target"], sort_keys=True), k, seed,
            id(current()))


def gold_draws(instance: dict, seed: int = PROBE_SEED) -> GoldDraws:
    """The episode's gold function and draws; HarnessFault when the gold program calls no function.
    Kept per process (DRAWS): the same gold program, board and seed give the same draws. Draws
    started ahead (`draw_ahead`) are waited for; drawn again here if they failed there."""
    gold_name, k, key = _plan(instance, seed)
    if gold_name is None:
        raise HarnessFault("probes: the gold program calls no function")
    _ahead.take(key, wait_queued=True)  # what it raised is not kept: a failed draw is drawn again below, in the step
    with _drawn_lock:
        known = _drawn.get(key)
    if known is not None:
        return GoldDraws(known.function, copy.deepcopy(known.draws))
    return _draw(instance, gold_name, k, seed, key)


def _plan(instance: dict, seed: int) -> tuple[str | None, int, tuple]:
    """What decides an episode's draws: the gold function's name, K and the key; (None, 0, ())
    when the gold program calls no function."""
    gold_name = probed_function(instance["gold_code"], instance["given_code"])
    if gold_name is None:
        return None, 0, ()
    k = int(instance.get("probes", DEFAULT_PROBES))
    return gold_name, k, _draws_key(instance, k, seed)


def _draw(instance: dict, gold_name: str, k: int, seed: int, key: tuple) -> GoldDraws:
    """Draw the episode's boards and keep them (DRAWS)."""
    drawn = GoldDraws(gold_name, draw_arguments(instance, instance["gold_code"], gold_name, k, seed))
    with _drawn_lock:
        _drawn[key] = GoldDraws(drawn.function, copy.deepcopy(drawn.draws))
        while len(_drawn) > DRAWS:
            _drawn.popitem(last=False)
    return drawn


# draws started at an episode's setup (ahead.py), by their key (gold_draws takes them; one whose
# step probes nothing, e.g. an answer without code, stays until DRAWS newer ones push it out)
_ahead = ahead.Started("setup", DRAWS)


def draw_ahead(instance: dict, seed: int = PROBE_SEED) -> None:
    """Start a probed episode's gold draws on the background thread (ahead.py); nothing for another
    episode. The draws are those `gold_draws` would make, which waits for them."""
    try:
        gold_name, k, key = _plan(instance, seed) if probed(instance) else (None, 0, ())
    except Exception:  # work ahead never fails a setup: the step draws again, and says why if it fails there
        return
    if gold_name is None:
        return
    with _drawn_lock:
        if key in _drawn:
            return
    _ahead.start(key, partial(_draw, instance, gold_name, k, seed, key))


def _forked() -> None:
    """In a forked child: a lock that no thread holds (the parent's drawer may have held it at the fork)."""
    global _drawn_lock
    _drawn_lock = threading.Lock()


os.register_at_fork(after_in_child=_forked)


def run_probes(instance: dict, code: str, seed: int = PROBE_SEED) -> dict:
    """The probes of one answer: {"function", "source", "gold_function", "probes": [{"colors", "x",
    "y", "category", "message"}], "share"} (share: probes built exactly / probes)."""
    result = run_probes_many([(instance, code, gold_draws(instance, seed))])[0]
    if isinstance(result, HarnessFault):
        raise result
    return result


class Probes(NamedTuple):
    """probe_programs' answer: the function probed, whose def it is, its probe programs."""
    function: str | None
    source: str | None
    programs: list[str]


def probe_programs(instance: dict, code: str, gold: GoldDraws) -> Probes:
    """The function an answer's `code` probes, whose def it is ("model" or "given": probed_call)
    and its probe programs, one per gold draw (None, None and none when it calls no function)."""
    given = instance["given_code"]
    found = probed_call(code, given)
    if found is None:
        return Probes(None, None, [])
    name, source = found
    head = probe_head(code, name, given_code=given, rows=instance["rows"], cols=instance["cols"])
    return Probes(name, source, [head + probe_call(name, a) for a, _ in gold.draws])


def run_probes_many(jobs: list[tuple[dict, str, GoldDraws]],
                    made: list[Probes] | None = None) -> list[dict | HarnessFault]:
    """`run_probes` of many (instance, answer code, gold draws) in one sandbox batch per board
    size, in input order; an answer whose probe the sandbox failed gets its HarnessFault.
    `made`: `probe_programs` of each job, when the caller has them already."""
    from .sandbox import judge, run_many

    plans: list[tuple[str | None, str | None, int, int]] = []
    batches: dict[tuple[int, int], list[str]] = {}
    labels: dict[tuple[int, int], list[int]] = {}
    for job, (instance, code, gold) in enumerate(jobs):
        rows, cols = instance["rows"], instance["cols"]
        name, source, programs = probe_programs(instance, code, gold) if made is None else made[job]
        batch = batches.setdefault((rows, cols), [])
        plans.append((name, source, len(batch), len(programs)))
        batch.extend(programs)
        labels.setdefault((rows, cols), []).extend([job] * len(programs))  # one answer's probes may share a child
    runs = {size: run_many(programs, *size, answers=labels[size]) for size, programs in batches.items()}
    out: list[dict | HarnessFault] = []
    for (instance, code, gold), (name, source, start, n) in zip(jobs, plans):
        probes = [{**args, "category": NO_FUNCTION, "message": "the answer calls no function"} for args, _ in gold.draws]
        executions = runs[(instance["rows"], instance["cols"])][start:start + n]
        fault = next((ex for ex in executions if ex.error == ErrorCode.HARNESS_ERROR), None)
        if fault is not None:
            out.append(HarnessFault(f"sandbox (probe): {fault.message}"))
            continue
        for probe, (_, gold_cells), ex in zip(probes, gold.draws, executions):
            verdict = judge(ex.ok, ex.error, ex.cells, gold_cells)
            probe["category"] = SUCCESS_CATEGORY if verdict.es else str(ErrorCode(verdict.category))
            probe["message"] = ex.message or ""
        built = sum(p["category"] == SUCCESS_CATEGORY for p in probes)
        out.append({"function": name, "source": source, "gold_function": gold.function, "probes": probes,
                    "share": built / len(probes) if probes else None})
    return out


def log_probes(game_master, instance: dict, record) -> None:
    """Probe a finished episode's build `record` (sartco.clem.core.building.BuildRecord) and record it
    under PROBES_KEY: probed episodes only, and only when the answer held code to run."""
    if probed(instance) and record.error != ErrorCode.PARSE_ERROR:
        game_master.log_key(PROBES_KEY, run_probes(instance, record.builder_code))
