"""BuildScorer's attempt scores, from the experiment's attempts (the rule the master plays by)."""
from __future__ import annotations

import json
import math

from clemcore.clemgame.metrics import KEY_EPISODE_SCORES

from sartco.clem.core.building import BuildRecord, build, parse_failure
from sartco.clem.core.scoring import BuildScorer
from sartco.world import SUCCESS_CATEGORY, ErrorCode
from sartco.episode import ATTEMPT_CATEGORIES, ATTEMPTS, ATTEMPTS_KEY, ES_AT_1, ES_AT_N, MAX_ATTEMPTS

TARGET = {"0:0": [["washer", "red"]]}


def scores(experiment: dict, interactions: dict) -> dict:
    scorer = BuildScorer("cobot_instruct", experiment, {"game_id": 0, "gold_code": ""})
    wrong = build("put(board, 'washer', 'blue', 0, 0)", TARGET)
    right = build("put(board, 'washer', 'red', 0, 0)", TARGET)
    interactions = {ATTEMPTS_KEY: [wrong.to_json(), right.to_json()], **interactions}
    scorer.log_attempt_scores(interactions, right, aborted=False)
    return scorer.scores[KEY_EPISODE_SCORES]


def test_attempt_scores_of_a_feedback_experiment():
    got = scores({"name": "x", "attempts": 3}, {})
    assert (got[ES_AT_1], got[ES_AT_N], got[ATTEMPTS], got[MAX_ATTEMPTS]) == (0, 1, 2, 3)
    assert got[ATTEMPT_CATEGORIES] == "mismatch_color,success"


def test_single_attempt_experiments_have_no_attempt_scores():
    assert scores({"name": "x"}, {}) == {}
    assert scores({"name": "x", "attempts": 1}, {}) == {}
    assert not math.isnan(scores({"name": "x", "attempts": 2}, {})[ES_AT_1])


def test_a_build_record_is_typed_and_its_json_is_plain_strings():
    """error is an ErrorCode, category an ErrorCode or SUCCESS_CATEGORY; interactions.json holds
    their strings, and reading the record back gives the typed record again."""
    target = {"0:0": [["nut", "red"]]}
    for record, error, category in [(build("put(board, 'nut', 'red', 0, 0)", target), None, "success"),
                                    (build("put(board, 'nut', 'blue', 0, 0)", target), None, "mismatch_color"),
                                    (build("undefined_name", target), "name_error", "name_error"),
                                    (parse_failure(target, "no code"), "parse_error", "parse_error")]:
        assert record.error is (None if error is None else ErrorCode(error))
        assert record.category is (SUCCESS_CATEGORY if category == "success" else ErrorCode(category))
        text = json.dumps(record.to_json())
        assert (f'"error": "{error}"' if error else '"error": null') in text and f'"category": "{category}"' in text
        back = BuildRecord.from_json(json.loads(text))
        assert back == record and type(back.category) is type(record.category) and type(back.error) is type(record.error)
