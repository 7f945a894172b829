"""clemcore backend `rulebased`: the rule-based follower as a model, `clem run -g cobot_instruct
-m rulebased`. A packaged backend file (sartco.clem.packaged): clemcore loads it by its path, as
it loads a <backend>_api.py of the working directory, and takes the one Backend subclass in it."""
from sartco.clem.tooling.rulebased import RulebasedBackend  # noqa: F401
