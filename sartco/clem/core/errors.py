"""The game core's exceptions, one small hierarchy in one place (as clemcore's errors.py):

    GameCoreError          the base: what the game core raises on purpose
    +- ParseError          no code in a builder's answer (sartco.clem.core.parsing): the attempt is
    |                      parse_error, the episode aborted; also a clemcore ParseError, so that
    |                      DialogueGameMaster.step counts the request as violated
    +- HarnessFault        the harness, not the model, failed: the sandbox gave harness_error, or the
    |                      game master or the scorer raised (sartco.clem.core.harness records the
    |                      episode as harness_error, aborted, never the model's error)
    +- InstanceFileError   an instance file a game cannot play (sartco.clem.core.instance_checks); the
    |                      message is one line naming file, experiment and field
    +- ProvenanceError     a results folder whose runs cannot be merged or checked
                           (sartco.clem.core.runs); one line naming the folder

A user's mistake outside a game (a bad option, a missing dataset) is sartco.errors.UserError; a
program's failure in the sandbox is no exception here but its ErrorCode (sartco.world).
"""
from __future__ import annotations

from clemcore.clemgame.errors import ParseError as _ClemParseError

from sartco.world import ErrorCode


class GameCoreError(Exception):
    """The base of the game core's exceptions."""


class ParseError(_ClemParseError, GameCoreError):
    """No code in the answer. A clemcore ParseError, so DialogueGameMaster.step counts it as a
    violated request; `code` is the sartco error vocabulary's name for it."""

    code = ErrorCode.PARSE_ERROR

    def __init__(self, reason: str, response: str | None = None):
        _ClemParseError.__init__(self, reason=reason, response=response, key=ErrorCode.PARSE_ERROR.value)


class HarnessFault(GameCoreError):
    """The harness, not the model, failed (the sandbox gave harness_error, or the game master or
    the scorer raised): sartco.clem.core.harness records the episode as harness_error, aborted."""

    def __init__(self, reason: str):
        super().__init__(reason)
        self.reason = reason


class InstanceFileError(GameCoreError):
    """An instance file a game cannot play; the message is one line naming file, experiment, field."""


class ProvenanceError(GameCoreError):
    """A results folder whose runs cannot be merged or checked; one line naming the folder."""
