"""Where sartco finds things and what it may spend: the one module that knows the package's own
folder, the checkout it may run from, the data folder and the folders that ship with the package,
and every default budget. Free of sartco imports (the bottom layer, beside sartco.dataset).

    PACKAGE      sartco/ itself (site-packages/sartco in a wheel install)
    CHECKOUT     the source checkout the package runs from (an editable install: the folder holding
                 pyproject.toml, games/ and sartco/), or None (a wheel install)
    DATA         the SARTCo data folder (published/, gold_boards/, paper-protocol/), read where it
                 lies, never copied: $SARTCO_DATA (the `sartco --data DIR` option sets it), else
                 ../shared/sartco-data beside the checkout; None when neither is given. Resolved
                 once, when this module is imported.
    RESOURCES    the generation templates and configs (resources/): $SARTCO_RESOURCES, else the
                 checkout's resources/, else the copy inside the package (sartco/resources in a wheel)
    GAMES        the game folders' files (clemgame.json, master.py, instancegenerator.py): the
                 checkout's games/, else the copy inside the package (sartco/games in a wheel);
                 `sartco games DIR` copies them where instances can be written (sartco.register)
    BACKENDS     the clemcore backends and model entries sartco brings (sartco/clem/backends);
                 `sartco register DIR` makes clemcore find them in DIR (sartco.register)
    workspace()  the folder relative defaults are read from (instances/v1, instances/published,
                 games/): the checkout, else the working directory

and every default budget (below "Budgets"): what one program may spend in the sandbox, how many
attempts, questions, corrections and function probes an episode has unless its instance file
says otherwise, and how long the batching backend waits for a model server.

setup.py copies resources/ and the game files into the package when it builds a wheel; an editable
install reads them in the checkout.
"""
from __future__ import annotations

import os
from pathlib import Path

ENV_DATA = "SARTCO_DATA"
ENV_RESOURCES = "SARTCO_RESOURCES"
DATA_SETTING = f"${ENV_DATA} or `sartco --data DIR`"

PACKAGE = Path(__file__).resolve().parent
BACKENDS = PACKAGE / "clem" / "backends"


def _checkout(package: Path) -> Path | None:
    root = package.parent
    if (root / "pyproject.toml").is_file() and (root / "games").is_dir() and (root / "resources").is_dir():
        return root
    return None


CHECKOUT = _checkout(PACKAGE)
# the folder Python must have on sys.path to import sartco (the sandbox's workers start from it)
IMPORT_ROOT = PACKAGE.parent


def _data() -> Path | None:
    given = os.environ.get(ENV_DATA)
    if given:
        return Path(given).expanduser().resolve()
    if CHECKOUT is not None:
        return CHECKOUT.parent / "shared" / "sartco-data"
    return None


DATA = _data()
# where DATA stands for a path that names no folder (a wheel install without $SARTCO_DATA): never
# exists, so every read of it ends in data_error's one line
_NO_DATA = Path("/nonexistent-sartco-data")


def data_path(*parts: str) -> Path:
    """A path inside the data folder (it may not exist: readers call data_error when it does not)."""
    return (DATA or _NO_DATA).joinpath(*parts)


def data_error(path: Path) -> str | None:
    """The one message for a missing data folder, when `path` lies inside the configured (or the
    missing) data folder and the folder is not there; None otherwise (another path, or it exists)."""
    root = DATA or _NO_DATA
    if not Path(path).is_relative_to(root) or root.is_dir():
        return None
    if DATA is None:
        return f"no SARTCo data folder: set {DATA_SETTING} (the folder with published/, gold_boards/, paper-protocol/)"
    return (f"SARTCo data folder {DATA} not found: set {DATA_SETTING} "
            f"(the folder with published/, gold_boards/, paper-protocol/)")


def _first_dir(*candidates: Path | None) -> Path:
    found = [c for c in candidates if c is not None and c.is_dir()]
    return found[0] if found else next(c for c in candidates if c is not None)


def resources_dir() -> Path:
    """RESOURCES (read when asked, so that $SARTCO_RESOURCES set by a caller counts)."""
    given = os.environ.get(ENV_RESOURCES)
    return _first_dir(Path(given) if given else None, CHECKOUT / "resources" if CHECKOUT else None,
                      PACKAGE / "resources")


GAMES = _first_dir(CHECKOUT / "games" if CHECKOUT else None, PACKAGE / "games")
GAME_NAMES = ("cobot_instruct", "cobot_describe")
GAME_FILES = ("clemgame.json", "master.py", "instancegenerator.py", "README.md")  # of each game: what ships


def workspace() -> Path:
    """The folder relative defaults are read from: the checkout, else the working directory."""
    return CHECKOUT if CHECKOUT is not None else Path.cwd()


def shown(path: Path) -> str:
    """A path as instance files and run records write it: relative to the workspace."""
    return os.path.relpath(path, workspace())


# Budgets: the defaults; an instance file's field, an experiment's field or a model entry's
# setting, where it has one, takes precedence (the modules named say which).
# One program in the sandbox (sartco.program.Limits): steps (loop iterations, calls, comprehension
# items), call depth, the longest sequence a checked operation may create, the largest integer in
# bits, wall seconds (the worker is killed), bytes of address space the worker may add, source characters
SANDBOX_STEPS = 1_000_000
SANDBOX_DEPTH = 200
SANDBOX_LENGTH = 1_000_000
SANDBOX_INT_BITS = 65_536
SANDBOX_WALL_TIME = 2.0
SANDBOX_MEMORY = 512 * 1024 * 1024
SANDBOX_SOURCE = 100_000
# An episode (instance and experiment fields; sartco.clem.core.feedback, .probes, sartco.games.describe.dialogue)
ATTEMPTS = 1                 # builds per episode without feedback (1 = the paper's protocol)
FEEDBACK_ATTEMPTS = 3        # builds per episode in the feedback experiments (`sartco instances --attempts`)
PROBES = 8                   # held-out arguments a probed function is called at (instance field `probes`)
QUESTIONS = 2                # clarification questions of the modes that clarify (experiment field `questions`)
CORRECTIONS = 3              # describer's corrections of the modes that correct (experiment field `corrections`)
# A model server, per model (the batching backend, sartco.clem.tooling.batching; a model entry's
# model_config takes precedence): requests in flight, retries after a failed try, seconds
# before the first retry (doubling), seconds per try, seconds of retrying per request at most
MODEL_SERVER = {"concurrency": 16, "retries": 5, "backoff": 1.0, "timeout": 120.0, "retry_budget": 600.0}
# The erring players (sartco.clem.players.erring; `-m erring`): the player seed, the share of pieces
# that slip, the chance that a slip other than the first is fixed after a feedback. run.json records
# them (sartco.clem.core.provenance).
ERRING_SEED = 42
ERRING_RATE = 0.3
ERRING_FIX = 0.5
