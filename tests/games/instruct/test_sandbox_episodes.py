"""Programs that attack the sandbox's results through clemcore's real loop: every episode ends
scored (interactions.json and scores.json written, strict JSON, valid UTF-8), with the failure
recorded as the episode's error category, and the gold episode after them still succeeds.

The surrogate case: a TypeError whose message holds a lone surrogate (`put(**{'\\ud800': 1})`)
made clemcore fail to write interactions.json, leaving the episode unscored."""
import json

from episode_helpers import GOLD, SINGLE, instance, outcome
from play_helpers import fence

ATTACKS = {
    # name: (code, category)
    "lone surrogate keyword": ("put(**{'\\ud800': 1})", "type_error"),
    "lone surrogate raised": ("raise ValueError('\\udfff' * 3)", "value_error"),
    "control characters": ("raise KeyError('\\x1b[31mred\\x00\\x07\\u202e')", "key_error"),
    "crash": ("x = [1]\nfor i in range(300000):\n    x = map(abs, x)\ny = list(x)", "runtime_error"),
    "memory": ("x = [[0] * 10**6 for i in range(1000)]", ("resource_limit", "timeout")),
}


def test_every_attack_episode_is_scored(play_episodes):
    names = list(ATTACKS)
    instances = [instance(i, [fence(ATTACKS[n][0])]) for i, n in enumerate(names)]
    instances.append(instance(len(names), [fence("\n".join(GOLD))]))
    results = play_episodes(instances, dict(SINGLE, name="sandbox_attacks"))
    assert len(results) == len(names) + 1
    for name, result in zip(names, results):
        for file in ("interactions.json", "scores.json"):
            text = (result["dir"] / file).read_bytes().decode("utf-8", errors="strict")
            _all_unicode(json.loads(text), (name, file))  # no lone surrogate, not even as a \\u escape
        s = result["scores"]["episode scores"]
        expected = ATTACKS[name][1]
        assert outcome(result["scores"]) == "lose", name
        assert s["Error Category"] in ((expected,) if isinstance(expected, str) else expected), name
        assert s["Main Score"] == 0.0
        message = result["interactions"]["sartco_build"]["message"]
        assert message and message.isprintable(), (name, message)
    s = results[-1]["scores"]["episode scores"]
    assert (outcome(results[-1]["scores"]), s["Main Score"]) == ("success", 100.0)


def _all_unicode(value, where):
    if isinstance(value, str):
        value.encode("utf-8")  # raises on a lone surrogate
    elif isinstance(value, dict):
        for k, v in value.items():
            _all_unicode(k, where)
            _all_unicode(v, where)
    elif isinstance(value, list):
        for v in value:
            _all_unicode(v, where)
