"""`sartco check-instances FILE`: the check `clem run` makes of an instance file before any model
is asked (sartco.clem.core.instance_checks.check_instances), without clem: exit 0 and one line when every
episode is playable, else exit 2 and one line naming the file, the experiment (and game_id) and the
field or value.

The fields an episode must have are the game's (its GameBenchmark's `fields_of`), so the game is
found as clem finds it: by default the game folder the file lies in (`<game>/in/FILE`), or by its
registry name with `-g` (as `clem run -g`: game_registry.json and the game folders below the
working directory).
"""
from __future__ import annotations

import logging
import os

from clemcore.clemgame import GameBenchmark, GameRegistry, GameSpec

from sartco.errors import UserError

from .errors import InstanceFileError
from .instance_checks import check_instances


def configure(parser) -> None:
    parser.add_argument("file", help="an instance file, e.g. games/cobot_instruct/in/instances.json")
    parser.add_argument("-g", "--game", default=None,
                        help="the game whose episodes these are, by registry name (as clem run -g); "
                             "default: the game folder the file lies in")
    parser.add_argument("-e", "--experiment", default=None,
                        help="an experiment that must be in the file (as clem run -e)")


def game_spec_of(path: str, game: str | None) -> GameSpec:
    """The game spec whose master reads the file: `game` from the registry, else the game folder
    `path` lies in (the entry naming this file, else the folder's first)."""
    if game is not None:
        try:
            return GameRegistry.from_directories_and_cwd_files().get_game_specs_that_unify_with(game)[0]
        except ValueError:
            raise UserError(f"no game '{game}' in the game registry of {os.getcwd()}") from None
    folder = os.path.dirname(os.path.dirname(os.path.abspath(path)))
    if os.path.basename(os.path.dirname(os.path.abspath(path))) != "in" \
            or not os.path.isfile(os.path.join(folder, "clemgame.json")):
        raise UserError(f"{path}: not in the in/ folder of a game; name its game with -g")
    specs = GameSpec.from_directory(folder)
    stem = os.path.splitext(os.path.basename(path))[0]
    return next((s for s in specs if getattr(s, "instances", None) == stem), specs[0])


def run(args) -> int:
    logging.disable(logging.INFO)  # clemcore logs its registry lookups and game loading to stdout
    spec = game_spec_of(args.file, args.game)
    with GameBenchmark.load_from_spec(spec) as benchmark:
        fields_of = getattr(benchmark, "fields_of", None)
        if fields_of is None:
            raise UserError(f"game {spec.game_name}: its benchmark names no episode fields (not a sartco game)")
        try:
            episodes = check_instances(args.file, fields_of, args.experiment)
        except InstanceFileError as error:
            raise UserError(str(error)) from None
    chosen = f"experiment {args.experiment}" if args.experiment else "all experiments"
    print(f"{args.file}: {episodes} episodes ({chosen}) fine for game {spec.game_name}")
    return 0
