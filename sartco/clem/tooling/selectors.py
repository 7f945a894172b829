"""What a command that plays (`sartco suite`, `sartco sample`, `sartco resume`) checks before any
model is asked: that clemcore knows each model (-m) and the game (-g), and that the instance file
(-i) and the experiment (-e) exist. Each problem is a UserError of one line naming the option, the
value and where to look, instead of clemcore's traceback after the run has started.
"""
from __future__ import annotations

import os

from sartco.errors import UserError


def check_models(models) -> None:
    """UserError for the first model no model registry clem reads here names (model_registry.json
    in the working folder, clemcore's own, sartco's registered ones)."""
    from clemcore.backends import ModelSpec
    from clemcore.backends.model_registry import ModelRegistry

    registry = ModelRegistry.from_packaged_and_cwd_files()
    for spec in ModelSpec.from_strings(list(models)):
        try:
            registry.get_first_model_spec_that_unify_with(spec)
        except ValueError:
            raise UserError(f"-m {spec.model_name}: no such model in clemcore's model registries (clemcore's own "
                            f"and {os.path.join(os.getcwd(), 'model_registry.json')}; `clem list models` lists them, "
                            f"docs/models.md says how to add yours)") from None


def game_spec(game: str):
    """The registered entry of `game` (clem run -g), or UserError naming the games clem sees here."""
    from clemcore.clemgame import GameRegistry

    registry = GameRegistry.from_directories_and_cwd_files()
    found = [s for s in registry.get_game_specs() if s.game_name == game]
    if not found:
        known = sorted({s.game_name for s in registry.get_game_specs()})
        raise UserError(f"-g {game}: no such game here ({os.getcwd()}); clem sees: {', '.join(known) or 'none'}")
    return found[0]


def check_instances(game: str, instances: str | None = None, experiment: str | None = None) -> None:
    """UserError when the game's instance file (clem run -i; None: the game's own) does not exist,
    is not an instance file, or has no experiment `experiment` (clem run -e)."""
    from sartco.clem.core.benchmark import instance_file
    from sartco.clem.core.errors import InstanceFileError
    from sartco.clem.core.instance_checks import check_instances as check

    spec = game_spec(game)
    if instances:
        spec.instances = instances
    try:
        check(instance_file(spec), {}, experiment)
    except InstanceFileError as error:
        option = "-e" if experiment and "no experiment" in str(error) else "-i"
        raise UserError(f"{option} {experiment if option == '-e' else instances or spec.instances}: {error}") from None
