# written by `sartco register`: clemcore loads this file by its path; the backend is in the sartco package
"""clemcore backend `rulebased`: the rule-based follower as a model, `clem run -g cobot_instruct
-m rulebased`. `sartco register DIR` copies this file to DIR/rulebased_api.py (sartco.register): clemcore
loads a <backend>_api.py of the working directory by its path and takes the one Backend subclass in it."""
from sartco.clem.tooling.rulebased import RulebasedBackend  # noqa: F401
