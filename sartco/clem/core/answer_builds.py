"""An answer's build: `build_for` (sartco.clem.core.building's `build` with the episode's board
fields), which a game master calls once the answer is final, and `start_build`, which starts the
same build on a background thread (ahead.py, lane "answers") as soon as the answer comes in.

clemcore's batchwise runner hands a round's answers to their players (Player.perceive_response)
before it steps the first of the round's episodes; the builder player passes its answer to its
game master's hook (sartco.clem.players.sourced.SourcedPlayer.on_answer), which starts the build
its step will make. While clemcore steps the earlier episodes, the sandbox builds the later ones.
The build is the step's own: build_for takes the one started if it has begun (and drops it if
it has not, so that no step waits behind the others' builds), and builds again in the step when
it failed there. The sandbox gives the same program the same build in every process, so the
record is the same either way.
"""
from __future__ import annotations

import json
from collections.abc import Mapping
from functools import partial
from typing import Any

from sartco.world import ErrorCode

from . import ahead, building
from .building import BuildRecord, sandbox_fault


def build_for(instance: Mapping[str, Any], builder_code: str, turn_codes: list[str] | None = None) -> BuildRecord:
    """`build` with the target, given code and board size of a game instance (the fields of
    sartco.clem.core.instance_files.board_fields); HarnessFault when the sandbox failed (harness_error).
    A build started when the answer came in (`start_build`) is waited for if it has begun (else
    dropped), and built again here if it failed there."""
    record = _started.take(_build_key(instance, builder_code, turn_codes), wait_queued=False)
    if not isinstance(record, BuildRecord) or record.error == ErrorCode.HARNESS_ERROR:
        record = _build_for(instance, builder_code, turn_codes)
    if record.error == ErrorCode.HARNESS_ERROR:
        raise sandbox_fault(record)
    return record


def _build_for(instance: Mapping[str, Any], builder_code: str, turn_codes: list[str] | None) -> BuildRecord:
    return building.build(builder_code, instance["target"], given_code=instance["given_code"],
                          rows=instance["rows"], cols=instance["cols"], turn_codes=turn_codes)


# builds started when their answer came in (STARTED at most: an answer whose step builds
# something else leaves its build until it is pushed out)
STARTED = 1024
_started = ahead.Started("answers", STARTED)


def _build_key(instance: Mapping[str, Any], builder_code: str, turn_codes: list[str] | None) -> str:
    return json.dumps([builder_code, turn_codes, instance["given_code"], instance["rows"], instance["cols"],
                       instance["target"]], sort_keys=True)


def start_build(instance: Mapping[str, Any], builder_code: str, turn_codes: list[str] | None = None) -> None:
    """Start `build_for`'s build on a background thread (ahead.py, lane "answers") when the answer
    comes in: clemcore's batchwise runner hands a round's answers to their players before it steps
    the first of its episodes, so the sandbox builds the later ones while the earlier are stepped.
    The same build as the step's (build_for takes it)."""
    _started.start(_build_key(instance, builder_code, turn_codes), partial(_build_for, instance, builder_code, turn_codes))
