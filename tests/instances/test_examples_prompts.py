"""In-context selection and the prompt's ablation switches."""
import pytest

from sartco.instances.examples import location, select_examples
from sartco.instances.prompts import SECTIONS, builder_prompt, builder_turn, describer_prompt
from sartco.world.render import grid_text


def _pool(files, kind):
    return files[f"{kind}_train.json"]


@pytest.mark.parametrize("kind", ["simple_simple", "regular_simple", "regular_complex"])
def test_examples_share_neither_combo_nor_location(dataset, kind):
    _, files = dataset
    pool = _pool(files, kind)
    for item in files[f"{kind}_test.json"][:40]:
        chosen = select_examples(item, pool, k=5, rng=3)
        assert len(chosen) == 5
        for ex in chosen:
            assert ex["split"] == "train"
            assert ex["combo_name"] != item["combo_name"]
            assert location(ex) != location(item)
        assert len({ex["combo_name"] for ex in chosen}) == 5
        assert [e["id"] for e in select_examples(item, pool, 5, 3)] == [e["id"] for e in chosen]


def test_examples_deterministic_and_sized(dataset):
    _, files = dataset
    pool, item = _pool(files, "simple_simple"), files["simple_simple_val.json"][0]
    for k in range(11):
        assert len(select_examples(item, pool, k, 0)) == k
    assert select_examples(item, pool, 5, 0) != select_examples(item, pool, 5, 1)
    with pytest.raises(ValueError):
        select_examples(item, pool, 11)


@pytest.mark.parametrize("task, kind", [("first_order", "simple_simple"), ("sequence_function", "simple_simple"),
                                        ("optimal_function", "simple_simple"), ("repetition", "regular_complex")])
def test_prompt_sections_and_examples(dataset, task, kind):
    _, files = dataset
    item = files[f"{kind}_test.json"][7]
    pool = _pool(files, kind)
    full = builder_prompt(item, task, select_examples(item, pool, 3, 0))
    for header in ("Environment:", "Task:", "Examples:", "Other details:"):
        assert header in full
    assert full.count("Instruction:") >= 4
    assert ("Context:" in full) == (task == "repetition")
    assert full.index("Environment:") < full.index("Task:") < full.index("Examples:") < full.index("Other details:")
    zero = builder_prompt(item, task, [])
    assert "Examples:" not in zero and zero.count("Instruction:") == 1
    for section, marker in (("environment", "Environment:"), ("task", "Task:"), ("details", "Other details:"),
                            ("system", "helpful assistant")):
        without = builder_prompt(item, task, [], sections=[s for s in SECTIONS if s != section])
        assert marker not in without and marker in zero
    if task == "repetition":
        assert item["code"]["repetition"]["function"] in full
        assert "Context:" not in builder_prompt(item, task, [], sections=[s for s in SECTIONS if s != "context"])
    assert builder_prompt(item, task, [], sections=[]).startswith("Instruction: ")
    with pytest.raises(ValueError):
        builder_prompt(item, task, pool[:11])
    with pytest.raises(ValueError):
        builder_prompt(item, task, [], sections=["nope"])


def test_prompt_labels(dataset):
    _, files = dataset
    item = files["simple_simple_test.json"][0]
    ex = select_examples(item, _pool(files, "simple_simple"), 1, 0)
    assert "Function:" in builder_prompt(item, "optimal_function", ex)
    assert "Usage:" in builder_prompt(item, "sequence_function", ex)
    first = builder_prompt(item, "first_order", ex)
    assert "Output:" in first and first.rstrip().endswith(item["instructions"]["template"]["multi_turn"][0])
    assert builder_turn(item, 1) == f"Instruction: {item['instructions']['template']['multi_turn'][1]}\n"
    with pytest.raises(ValueError):
        builder_prompt(item, "repetition", [])


def test_describer_prompt(dataset):
    _, files = dataset
    item = files["regular_simple_val.json"][3]
    text = describer_prompt(item)
    assert grid_text(item["target"]) in text and f"'{item['combo_name']}'" in text
    assert text.rstrip().endswith('Answer under the label "Instruction:" and write nothing else.')
