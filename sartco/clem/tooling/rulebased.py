"""The clemcore backend that makes the rule-based follower selectable as a model: `clem run -g
cobot_instruct -m rulebased`. `sartco register DIR` (sartco.register) writes its entry
{"model_name": "rulebased", "backend": "rulebased"} and backend file (sartco/clem/backends) into DIR,
beside the user's own entries in DIR/model_registry.json.

The model is a CustomResponseModel, so clemcore's Player answers from the player's answer source,
chosen by this model name when the player is made (sartco.clem.players.answers.instruct_answers: the
follower instead of the gold code; sartco.games.describe.players in cobot_describe). The same
backend serves `erring` (entry {"model_name": "erring", "backend": "rulebased"}): the follower
with seeded mistakes (sartco.clem.players.erring).
"""
from __future__ import annotations

from clemcore.backends import Backend, CustomResponseModel, Model, ModelSpec

from sartco.clem.players.sourced import ERRING, RULEBASED


class RulebasedModel(CustomResponseModel):
    def supports_batching(self) -> bool:
        # clemcore's batch path only injects players for the names mock/programmatic
        return False


class RulebasedBackend(Backend):
    def get_model_for(self, model_spec: ModelSpec) -> Model:
        if model_spec.model_name not in (RULEBASED, ERRING):
            raise ValueError(f"the rulebased backend serves only the models '{RULEBASED}' and '{ERRING}', "
                             f"not {model_spec.model_name!r}")
        return RulebasedModel(model_spec)
