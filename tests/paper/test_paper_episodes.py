"""Paper-protocol episodes against the README rules, re-derived here from the published files
and the template text (nothing below is a stored prompt)."""
import random
from collections import Counter
from pathlib import Path

import pytest

from sartco.errors import UserError
from sartco.paper import PROTOCOL
from sartco.paper.episodes import build_episodes
from sartco.paper.reading import read_answer

from paper_helpers import DATA, GENERATED, PROTOCOL_DIR, PUBLISHED, read_json

TEMPLATE = {"multi_turn": "builder_multi_turn", "single_turn": "builder_single_turn", "single_turn_sc": "builder_single_turn",
            "single_turn_hai": "builder_single_turn", "single_turn_hai_sc": "builder_single_turn",
            "single_turn_mg": "builder_single_turn", "regular": "builder_regular", "regular_hai": "builder_regular",
            "regular_mg": "builder_regular"}
TRAINING = {"single_turn_hai": "single_turn", "single_turn_mg": "single_turn", "single_turn_hai_sc": "single_turn_sc",
            "regular_hai": "regular", "regular_mg": "regular"}


def walk(content):
    """(sample id, sample) in file order."""
    for board, by_object in content.items():
        for obj, by_count in by_object.items():
            for count, by_combo in by_count.items():
                for combo, items in by_combo.items():
                    for i, sample in enumerate(items):
                        yield f"{board}/{obj}/{count}/{combo}/{i}", sample


def answer_part(variant, editor):
    if variant.startswith("single_turn"):
        return "\n\nFunction\n" + editor["function"] + "\n\nUsage\n" + editor["usage"] + "\n"
    if variant.startswith("regular"):
        return "\n\nOutput\n" + editor["output"] + "\n"
    return "\n\nOutput\n" + editor + "\n"


def fill(template_text, variant, sample, block):
    """The README's substitution, done by hand (longest names first so that no prefix is cut)."""
    names = {"INSTRUCTION_LABEL": "Instruction", "INCONTEXT_SAMPLES": block}
    if variant.startswith("single_turn"):
        names.update(OUTPUT_LABEL_HORDER_USAGE="Usage", OUTPUT_LABEL_HORDER="Function")
    else:
        names["OUTPUT_LABEL"] = "Output"
    if variant.startswith("regular"):
        names.update(COMBO_NAME=sample["combo_name"], COLORS=str(sample["colors"]))
    for name in sorted(names, key=len, reverse=True):
        template_text = template_text.replace("$" + name, names[name])
    return template_text


def published_candidates(train_content, variant, count, combo, seed_template):
    training = TRAINING.get(variant, variant)
    out = []
    for sid, sample in walk(train_content):
        _, _, c, cmb, _ = sid.split("/")
        if c != count or cmb == combo or sample["seed_template"] == seed_template:
            continue
        for turn in sample["dialogues"][training]["instructions"]:
            out.append("Instruction\n" + turn["<Programmer>"] + answer_part(variant, turn["<Editor>"]))
    return out


def sample_five(candidates):
    state = random.getstate()
    try:
        random.seed("42")
        return random.sample(candidates, 5)
    finally:
        random.setstate(state)


RB_SO_FILES = ["rb_so_test", "rb_so_test_hc", "rb_so_test_mg", "rb_so_test_gpt4_mg", "rb_so_test_claude_mg"]


def test_rb_so_messages_are_byte_for_byte_the_authors(by_id):
    """Every published rb_so test sample and variant: examples from the published training file."""
    train = read_json(PUBLISHED / "rb_so_train.json")
    checked = 0
    for stem in RB_SO_FILES:
        content = read_json(PUBLISHED / f"{stem}.json")
        variant = {"rb_so_test": "regular"}.get(stem, "regular_hai" if stem.endswith("_hc") else "regular_mg")
        for sid, sample in walk(content):
            _, _, count, combo, _ = sid.split("/")
            block = "\n".join(sample_five(published_candidates(train, variant, count, combo, sample["seed_template"])))
            text = sample["dialogues"][variant]["instructions"][0]["<Programmer>"]
            template = (PROTOCOL_DIR / f"{TEMPLATE[variant]}.template").read_text(encoding="utf-8")
            expected = fill(template, variant, sample, block) + "\nInstruction\n" + text + "\n"
            episode = by_id[f"{stem}/{sid}/{variant}"]
            assert episode.messages == [expected], episode.id
            assert episode.examples_from == "published rb_so_train"
            checked += 1
    assert checked == 5 * 130


def split_around_examples(variant, message, sample):
    template = (PROTOCOL_DIR / f"{TEMPLATE[variant]}.template").read_text(encoding="utf-8")
    head, tail = fill(template, variant, sample, "\x00").split("\x00")
    assert message.startswith(head)
    rest = message[len(head):]
    return head, rest, tail


@pytest.mark.parametrize("stem", ["sb_so_test", "sb_so_test_hc", "sb_so_test_mg", "sb_so_test_gpt4_mg",
                                  "sb_so_test_claude_mg", "rb_cho_test", "rb_cho_test_hc"])
def test_other_files_everything_around_the_examples(stem, episodes):
    content = dict(walk(read_json(PUBLISHED / f"{stem}.json")))
    mine = [e for e in episodes if e.file == stem]
    assert len(mine) == 130 * (3 if stem == "sb_so_test" else 2 if stem == "sb_so_test_hc" else 1)
    for e in mine:
        sample = content[e.sample]
        turns = sample["dialogues"][e.variant]["instructions"]
        head, rest, tail = split_around_examples(e.variant, e.messages[0], sample)
        ending = tail + "\nInstruction\n" + turns[0]["<Programmer>"] + "\n"
        assert rest.endswith(ending), e.id
        block = rest[: -len(ending)]
        assert block.count("Instruction\n") == 5 and block.startswith("Instruction\n")
        label = "\n\nFunction\n" if e.variant.startswith("single_turn") else "\n\nOutput\n"
        assert block.count(label) == 5
        # later turns (multi_turn): the bare instruction under its label
        assert e.messages[1:] == ["Instruction\n" + t["<Programmer>"] + "\n" for t in turns[1:]]
        assert "generated v1 train split" in e.examples_from and "never published" in e.examples_from


def generated_candidates(records, variant, count, combo, arrangement):
    """Our generated train split, in the published candidate form and order, built by hand."""
    training = TRAINING.get(variant, variant)
    order = {}
    for r in records:
        order.setdefault(len(r["shapes"]), {}).setdefault(r["combo_name"], []).append(r)
    out = []
    for c in sorted(order):
        for cmb, group in order[c].items():
            for r in group:
                if str(c) != count or cmb == combo or (arrangement and r["arrangement"] == arrangement):
                    continue
                texts = r["instructions"]["template"]
                if training == "multi_turn":
                    for text, step in zip(texts["multi_turn"], r["code"]["first_order"]["steps"]):
                        out.append("Instruction\n" + text + answer_part("multi_turn", step))
                elif training == "regular":
                    out.append("Instruction\n" + texts["regular"] + answer_part("regular", r["code"]["repetition"]))
                else:
                    style = "optimal_function" if training == "single_turn" else "sequence_function"
                    out.append("Instruction\n" + texts["single_turn"] + answer_part("single_turn", r["code"][style]))
    return out


@pytest.mark.parametrize("stem,train_file", [("sb_so_test", "simple_simple_train.json"),
                                             ("sb_so_test_hc", "simple_simple_train.json"),
                                             ("rb_cho_test_hc", "regular_complex_train.json")])
def test_example_selection_rule_on_the_generated_split(stem, train_file, episodes):
    records = read_json(GENERATED / train_file)
    content = dict(walk(read_json(PUBLISHED / f"{stem}.json")))
    for e in [e for e in episodes if e.file == stem][::7]:
        sample = content[e.sample]
        _, _, count, combo, _ = e.sample.split("/")
        arrangement = Path(sample["seed_template"]).stem if e.variant.startswith("regular") else None
        block = "\n".join(sample_five(generated_candidates(records, e.variant, count, combo, arrangement)))
        assert block in e.messages[0], e.id


def test_examples_share_neither_combination_nor_seed_and_have_the_same_size(episodes):
    train = read_json(PUBLISHED / "rb_so_train.json")
    test = dict(walk(read_json(PUBLISHED / "rb_so_test.json")))
    for e in [e for e in episodes if e.file == "rb_so_test"][::13]:
        _, _, count, combo, _ = e.sample.split("/")
        sample = test[e.sample]
        prompt = e.messages[0].split("Lets begin")[0]
        chosen = [(sid, s) for sid, s in walk(train)
                  if "Instruction\n" + s["dialogues"]["regular"]["instructions"][0]["<Programmer>"] + "\n" in prompt]
        assert len(chosen) >= 5, e.id
        for sid, s in chosen:
            assert sid.split("/")[2] == count and s["combo_name"] != combo, e.id
            assert s["seed_template"] != sample["seed_template"], e.id


def test_two_samples_with_the_same_exclusions_get_the_same_examples(episodes):
    by_key = {}
    for e in episodes:
        if e.file == "sb_so_test" and e.variant == "single_turn":
            _, _, count, combo, _ = e.sample.split("/")
            block = e.messages[0].split("Lets begin")[0]
            by_key.setdefault((count, combo), set()).add(block)
    assert all(len(blocks) == 1 for blocks in by_key.values())
    assert len({b for blocks in by_key.values() for b in blocks}) > 10


def test_cells_ids_and_order(episodes):
    assert len(episodes) == 1950
    assert len({e.id for e in episodes}) == len(episodes)
    assert all(e.id == f"{e.file}/{e.sample}/{e.variant}" and e.protocol == PROTOCOL for e in episodes)
    cells = Counter((e.cell["instructions"], e.cell["board"], e.cell["object"], e.cell["task"], e.cell["source"])
                    for e in episodes)
    table3 = read_json(DATA / "paper-protocol" / "table3.json")
    for cell in table3["cells"]:
        sources = ["template"] if cell["instructions"] == "template" else ["human"] if cell["instructions"] == "human" \
            else ["codellama", "gpt4", "claude"]
        for source in sources:
            assert cells[(cell["instructions"], cell["board"], cell["object"], cell["task"], source)] == 130, cell
    # the only cell beyond Table 3: human-written instructions for the sequence function
    assert cells[("human", "simple", "simple", "sequence_function", "human")] == 130
    assert [e.id for e in build_episodes(files=["rb_cho_test_hc"])] == [e.id for e in episodes if e.file == "rb_cho_test_hc"]


def test_gold_target_and_mock_answers(episodes):
    boards = {stem: read_json(DATA / "gold_boards" / f"{stem}.json") for stem in ("sb_so_test", "rb_so_test", "rb_cho_test")}
    for e in episodes:
        base = "_".join(e.file.split("_")[:3])
        assert e.target == boards[base][e.sample]
        sample_turns = len(e.gold)
        assert len(e.messages) == len(e.mock_answers) == sample_turns
        if e.variant == "multi_turn":
            assert sample_turns >= 2 and set(e.gold[0]) == {"output"}
        elif e.variant.startswith("single_turn"):
            assert sample_turns == 1 and set(e.gold[0]) == {"function", "usage"}
            assert e.gold[0]["function"].endswith("\n" + e.gold[0]["usage"])
        else:
            assert sample_turns == 1 and set(e.gold[0]) == {"output"}
            assert e.given_function.startswith("def ")
        assert bool(e.given_function) == e.variant.startswith("regular")
        for answer, gold in zip(e.mock_answers, e.gold):
            read = read_answer(answer, e.variant)
            assert {k: [ln for ln in v.split("\n") if ln.strip()] for k, v in read.items()} == \
                   {k: [ln for ln in v.split("\n") if ln.strip()] for k, v in gold.items()}


def test_to_json_round_trip_and_determinism(episodes):
    again = build_episodes(files=["sb_so_test_hc"], variants=["single_turn_hai"])
    mine = [e for e in episodes if e.file == "sb_so_test_hc" and e.variant == "single_turn_hai"]
    assert [e.to_json() for e in again] == [e.to_json() for e in mine]
    data = mine[0].to_json()
    assert {"id", "protocol", "file", "sample", "variant", "cell", "messages", "gold", "given_function", "target",
            "examples_from", "mock_answers"} <= set(data)
    assert type(mine[0]).from_json(data) == mine[0]


def test_unknown_names_are_user_errors(tmp_path):
    with pytest.raises(UserError, match="unknown test file"):
        build_episodes(files=["sb_so_train"])
    with pytest.raises(UserError, match="unknown variant"):
        build_episodes(variants=["regular_x"])
    with pytest.raises(UserError, match="published test file missing"):
        build_episodes(published_dir=tmp_path, files=["rb_so_test"])
