"""clemcore backend `rulebased` (looked up as <backend>_api.py in the working directory):
the rule-based follower as a model, `clem run -g cobot_instruct -m rulebased`.
The implementation lives in the installed package (sartco.clem.rulebased)."""
from sartco.clem.rulebased import RulebasedBackend  # noqa: F401  (clemcore finds the Backend subclass)
