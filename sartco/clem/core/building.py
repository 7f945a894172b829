"""Run a builder's code through sartco.program and record what happened, as one JSON-able record.

The game master calls `build_for(instance, ...)` (answer_builds.py: `build` with the instance's board fields) once
per episode (or once per attempt in a repair experiment) and records each build with
`record_build`: its board event for the transcript and, for the build the episode ends with
(`final`), the record for the scorer and the game state (sartco.clem.core.outcomes). A build
that the sandbox could not run (`harness_error`) raises HarnessFault from `build_for`: the
master's harness guard (sartco.clem.core.harness) records it, never as the model's error. The
scorer reads the record back with `BuildRecord.from_json`; it never executes anything.

Every record is strict UTF-8 JSON: `build` and `parse_failure` escape the texts they are given
(sartco.text.escape, as the game master escapes every answer at its entry), so a lone surrogate
or a control character in the code is recorded, run and shown as the same visible escape, and
the sandbox's message is escaped alike. Escaping escaped text changes nothing, so a game's
records (its answers are escaped before they get here) are the same as before.
"""
from __future__ import annotations

from dataclasses import dataclass, field, fields
from typing import cast

from sartco.episode import BUILD_KEY
from sartco.text import escape
from sartco.world import DEFAULT_COLS, DEFAULT_ROWS, SUCCESS_CATEGORY, Category, ErrorCode, category_family, category_of
from sartco.world.render import diff_svg, differing_cells

from .errors import HarnessFault
from .outcomes import set_attempts_outcome, set_share_outcome
from .transcript import code_block, picture, text_block

BOARD_EVENT = "board"               # the GM->GM event that shows target and built board
PICTURE = "boards.svg"              # the final build's picture, beside interactions.json
ATTEMPT_PICTURE = "boards_{}.svg"   # attempt 1, 2, ... (every episode has attempt 1)
PICTURE_ALT = "target (left) and built board (right); differing cells framed; a stack's pieces bottom to top"
# what the last step of an episode puts into clemcore's step info (the gym env's `info`): info key -> record field
INFO_FIELDS = {"es": "es", "cell_f1": "f1", "error_category": "category", "puts": "puts"}
# the same facts, under this key, in every player's context after the final build: the observation a
# trainer gets at the episode's end (clem serve's OpenEnv serialisation keeps the context and drops info)
CONTEXT_KEY = "sartco_scores"


@dataclass(frozen=True, slots=True)
class BuildRecord:
    builder_code: str                 # what the builder wrote (all turns joined)
    program: str                      # what was executed: init_board + given code + builder code
    ok: bool                          # the program ran to the end
    error: ErrorCode | None           # when the program failed (or parse_error, harness_error)
    message: str
    cells: dict                       # the board built (so far, when the program failed)
    target: dict
    puts: int
    es: int                           # 1 when cells == target and ok
    category: Category                # the error, the mismatch category, or SUCCESS_CATEGORY
    precision: float
    recall: float
    f1: float
    rows: int = DEFAULT_ROWS
    cols: int = DEFAULT_COLS
    turn_codes: list = field(default_factory=list)  # one entry per builder turn

    def to_json(self) -> dict:
        """The record as JSON data: a copy with fresh lists for the boards' stacks, as
        dataclasses.asdict makes it, at a tenth of its cost (every build of every episode is
        recorded); `error` and `category` stay members of str enums, which JSON writes as their
        strings."""
        data = {f.name: getattr(self, f.name) for f in fields(self)}
        for board in ("cells", "target"):
            data[board] = {key: [list(piece) for piece in stack] for key, stack in data[board].items()}
        data["turn_codes"] = list(self.turn_codes)
        return data

    def svg(self) -> str:
        """The picture of target beside built board (differing cells framed), as SVG."""
        return diff_svg(self.target, self.cells, self.rows, self.cols)

    @classmethod
    def from_json(cls, data: dict) -> "BuildRecord":
        names = {f.name for f in fields(cls)}
        values = {k: v for k, v in data.items() if k in names}
        values["error"] = None if values.get("error") is None else ErrorCode(values["error"])
        values["category"] = category_of(values["category"])
        return cls(**values)

    @property
    def family(self) -> str:
        return category_family(self.category)

    def summary(self) -> str:
        """One line for transcripts: what happened and where. Derived from the target too (cells
        that differ, P/R/F1): never send it to a player - sartco.clem.core.feedback is what a builder sees."""
        if self.category == SUCCESS_CATEGORY:
            return f"success: the target was built ({self.puts} puts)"
        if self.error in (ErrorCode.PARSE_ERROR, ErrorCode.HARNESS_ERROR):
            return f"{self.error}: {self.message}"
        diff = len(differing_cells(self.target, self.cells))
        detail = f" - {self.message}" if self.message else ""
        return (f"{self.category} ({self.family}){detail}; {self.puts} puts, {diff} cells differ, "
                f"cell P/R/F1 {self.precision:.2f}/{self.recall:.2f}/{self.f1:.2f}")


def compose_program(builder_code: str, *, given_code: str = "", rows: int = DEFAULT_ROWS,
                    cols: int = DEFAULT_COLS) -> str:
    """The program executed for an episode: the given code (e.g. the object function of a
    repetition task), a fresh board, then the builder's code - the paper's total_code layout."""
    parts = [given_code.strip()] if given_code.strip() else []
    parts.append(f"board = init_board({rows}, {cols})")
    parts.append(builder_code.strip())
    return "\n".join(parts) + "\n"


@dataclass(frozen=True, slots=True)
class BuildJob:
    """One build to run: the builder's code on a fresh board of the episode, against its target."""
    builder_code: str
    target: dict
    given_code: str = ""
    rows: int = DEFAULT_ROWS
    cols: int = DEFAULT_COLS
    turn_codes: list[str] | None = None


def build(builder_code: str, target: dict, *, given_code: str = "", rows: int = DEFAULT_ROWS, cols: int = DEFAULT_COLS,
          turn_codes: list[str] | None = None) -> BuildRecord:
    """Execute the builder's code (escaped: see the module's docstring) on a fresh board and
    compare it with the target."""
    return build_many([BuildJob(builder_code, target, given_code, rows, cols, turn_codes)])[0]


def build_many(jobs: list[BuildJob]) -> list[BuildRecord]:
    """`build` of many jobs, in input order: one sandbox batch per board size (sartco.clem.core.sandbox)."""
    from .sandbox import judge, run_many

    jobs = [escaped(j) for j in jobs]
    programs = [program_of(j) for j in jobs]
    executions: list = [None] * len(jobs)
    for (rows, cols), indices in _by_size(jobs).items():
        for i, ex in zip(indices, run_many([programs[i] for i in indices], rows, cols)):
            executions[i] = ex
    out = []
    for job, program, ex in zip(jobs, programs, executions):
        cmp = judge(ex.ok, ex.error, ex.cells, job.target)
        error = None if ex.error is None else ErrorCode(ex.error)  # sartco.program: set whenever not ok
        es = int(cmp.es)
        category: Category = SUCCESS_CATEGORY  # the error unless the program built the target
        if not es:
            if cmp.category is None:
                raise ValueError("sartco.program.judge: a failed build without a category")
            category = ErrorCode(cmp.category)
        out.append(BuildRecord(
            builder_code=job.builder_code, program=program, ok=bool(ex.ok), error=error, message=escape(ex.message or ""),
            cells=ex.cells, target=job.target, puts=int(ex.puts), es=es, category=category,
            precision=float(cmp.precision), recall=float(cmp.recall), f1=float(cmp.f1),
            rows=job.rows, cols=job.cols, turn_codes=list(job.turn_codes or [job.builder_code]),
        ))
    return out


def escaped(job: BuildJob) -> BuildJob:
    """The job with its texts escaped (the module's docstring), as build_many runs and records it."""
    return BuildJob(escape(job.builder_code), job.target, escape(job.given_code), job.rows, job.cols,
                    [escape(code) for code in job.turn_codes] if job.turn_codes else None)


def program_of(job: BuildJob) -> str:
    """The program an escaped job runs."""
    return compose_program(job.builder_code, given_code=job.given_code, rows=job.rows, cols=job.cols)


def _by_size(jobs) -> dict[tuple[int, int], list[int]]:
    """The positions of the jobs per board size (rows, cols), in input order."""
    sizes: dict[tuple[int, int], list[int]] = {}
    for i, job in enumerate(jobs):
        sizes.setdefault((job.rows, job.cols), []).append(i)
    return sizes


def parse_failure(target: dict, message: str, *, turn_codes: list[str] | None = None,
                  rows: int = DEFAULT_ROWS, cols: int = DEFAULT_COLS,
                  error: ErrorCode = ErrorCode.PARSE_ERROR) -> BuildRecord:
    """The record of an episode aborted because an answer held no code (or, with
    error=HARNESS_ERROR, because the harness failed): nothing was executed. Texts escaped."""
    turn_codes = [escape(code) for code in turn_codes or []]
    return BuildRecord(
        builder_code="\n".join(turn_codes), program="", ok=False, error=error, message=escape(message),
        cells={}, target=target, puts=0, es=0, category=error,
        precision=0.0, recall=0.0, f1=0.0, rows=rows, cols=cols, turn_codes=turn_codes,
    )


def sandbox_fault(record: BuildRecord) -> HarnessFault:
    """The harness fault of a build the sandbox could not run (category harness_error)."""
    return HarnessFault(f"sandbox: {record.message}")


def parse_failure_for(instance: dict, message: str, turn_codes: list[str] | None = None,
                      error: ErrorCode = ErrorCode.PARSE_ERROR) -> BuildRecord:
    """`parse_failure` with the target and board size of a game instance."""
    return parse_failure(instance["target"], message, turn_codes=turn_codes,
                         rows=instance["rows"], cols=instance["cols"], error=error)


def build_answers(instance: dict, answers: list[str]) -> BuildRecord:
    """Our build of a dialogue's answers: the code sartco.clem.core.parsing finds in each, joined and run
    once; the first answer without code makes it a parse failure (nothing executed). HarnessFault
    when the sandbox failed."""
    record = build_answers_many([(instance, answers)])[0]
    if record.error == ErrorCode.HARNESS_ERROR:
        raise sandbox_fault(record)
    return record


def build_answers_many(items: list[tuple[dict, list[str]]]) -> list[BuildRecord]:
    """`build_answers` of many (instance, answers) pairs in one sandbox batch per board size, in
    input order; a build the sandbox failed is returned as its harness_error record, not raised."""
    return build_jobs([answers_job(instance, answers) for instance, answers in items])


def build_jobs(jobs: list[BuildJob | BuildRecord]) -> list[BuildRecord]:
    """`build_many` of the jobs (answers_job's), in input order; a record (the parse failure of an
    answer without code) stands for itself."""
    out: list[BuildRecord | None] = [job if isinstance(job, BuildRecord) else None for job in jobs]
    places = [k for k, record in enumerate(out) if record is None]
    for k, record in zip(places, build_many([cast(BuildJob, jobs[k]) for k in places])):
        out[k] = record
    if any(record is None for record in out):
        raise RuntimeError("build_jobs: a job got no record")
    return cast("list[BuildRecord]", out)


def answers_job(instance: dict, answers: list[str]) -> BuildJob | BuildRecord:
    """The build of a dialogue's answers (build_answers): the code sartco.clem.core.parsing finds
    in each, joined; or the parse failure of the first answer without code."""
    from .errors import ParseError
    from .parsing import parse_code

    codes = []
    for answer in answers:
        try:
            codes.append(parse_code(answer))
        except ParseError as error:
            return parse_failure_for(instance, error.reason or "no code found", turn_codes=codes)
    return BuildJob("\n".join(codes), instance["target"], instance["given_code"], instance["rows"], instance["cols"],
                    codes)


def record_build(game_master, attempts: list[BuildRecord], *, final: bool, shown: bool = False,
                 instance: dict | None = None, share: float | None = None) -> None:
    """The one way a game master records a build: `attempts` are the episode's builds so far in
    order, the newest last.

    The newest build's board event (for the transcript, unless `shown`: logged when it was made):
    outcome line, the executed program as code and the picture of target and built board, inside
    the event so it shows whenever the transcript is made, linked to its full-size file
    ATTEMPT_PICTURE (attempt = its position), which `clem score` writes beside interactions.json
    (sartco.clem.core.pictures).
    `final`: the episode's result is the newest build. Record it for the scorer (BUILD_KEY), probe
    its function (with the episode's `instance`, sartco.clem.core.probes), move the game state to
    the outcome of the attempts (or, for the paper protocol, to the `share` of turns that succeeded)
    and hand ES, cell F1, category and puts to clemcore's step info (what a gym env's `info` and
    reward function see, sartco.games.instruct.training) and, under CONTEXT_KEY, to every player's
    context (the observation at the episode's end, also over `clem serve`; its text unchanged)."""
    from .probes import log_probes

    record = attempts[-1]
    if not shown:
        program = code_block(record.program) if record.program else text_block("(none: nothing was built)")
        content = "\n\n".join([text_block(record.summary()), text_block("executed program:"), program,
                                picture(record.svg(), ATTEMPT_PICTURE.format(len(attempts)), PICTURE_ALT)])
        game_master.log_event("GM", "GM", {"type": BOARD_EVENT, "content": content,
                                           "category": record.category})
    if not final:
        return
    game_master.log_key(BUILD_KEY, record.to_json())
    if instance is not None:
        log_probes(game_master, instance, record)
    if share is None:
        set_attempts_outcome(game_master.state, [a.category for a in attempts])
    else:
        set_share_outcome(game_master.state, share)
    facts = {key: getattr(record, name) for key, name in INFO_FIELDS.items()}
    game_master.info.update(facts)
    for player in game_master.get_players():
        context = game_master.get_context_for(player)
        if context is not None:  # a player who got no turn observes clemcore's "the game ended" text
            extras = {key: value for key, value in context.items() if key not in ("role", "content")}
            game_master.set_context_for(player, context["content"], **{**extras, CONTEXT_KEY: dict(facts)})
