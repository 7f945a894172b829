"""Instances of cobot_describe from a generated dataset's test split.

    python games/cobot_describe/instancegenerator.py [--dataset instances/v1] [--seed 42]
           [--examples 5] [--slice N]

One experiment per board kind, every test board of the dataset one episode:
  simple_boards                    simple boards (simple objects); the builder writes the optimal
                                   function (the paper's single-turn task of model-written instructions)
  regular_boards_simple_objects    regular boards of simple objects; the builder gets the object
  regular_boards_complex_objects   function and writes the repetition code (of complex objects)
The builder's prompt is cobot_instruct's (sartco.instances.prompts.builder_prompt) with `--examples`
in-context examples from the dataset's train split (select_examples, seeded by --seed); the
instruction slot is filled during the game with what the describer wrote. The instance file
names the dataset version and seed and the generator's seed.

Each board kind is played in every mode of sartco.clem.describe.dialogue.MODES: `oneshot` (the three
experiments above, named by the board kind only) in in/instances.json, the game entry
`cobot_describe` (the paper's one-shot game: its clemscore means that alone), and `<kind>_clarify`,
`<kind>_correct`, `<kind>_clarify_correct` (experiment fields `mode`, `questions` K = --questions,
`corrections` R = --corrections; the same boards and prompts, the builder's prompt of a clarify
mode ends with the paragraph on questions, sartco.clem.describe.dialogue.clarify_note) in
in/instances_dialogue.json, the entry `cobot_describe_dialogue`. Episode ids are numbered over
both files (mode by mode, as one file would), so they are unique across the two entries.

--slice N also writes in/instances_slice.json and in/instances_dialogue_slice.json with N episodes
per experiment, spread over the split, for a smoke run with a local model:
`clem run -g cobot_describe -m MODEL -i instances_slice`.
"""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

from sartco.clem.core.episodes import board_fields
from sartco.clem.core.instance_values import InstanceGenerator
from sartco.clem.describe.describer import INSTRUCTION_SLOT
from sartco.clem.describe.dialogue import DEFAULT_CORRECTIONS, DEFAULT_QUESTIONS, MODES, clarify_note
from sartco.dataset import BOARD_KINDS, DESCRIBED_TASK, BoardKind
from sartco.episode import DescribeEpisode, DescribeExperiment
from sartco.errors import UserError
from sartco.instances.examples import select_examples
from sartco.instances.storage import load_dataset
from sartco.instances.prompts import builder_prompt, describer_prompt, instruction_text

GAME_DIR = Path(__file__).resolve().parent
REPO = GAME_DIR.parents[1]
# instance file (clemgame.json entry) -> the modes it holds: cobot_describe is the paper's one-shot
# game alone (its clemscore means that), cobot_describe_dialogue the dialogue modes
ENTRY_FILES = {"instances": ("oneshot",), "instances_dialogue": tuple(m for m in MODES if m != "oneshot")}



def split_records(dataset: Path, files: dict[str, list[dict]], kind: BoardKind, split: str) -> list[dict]:
    """The records of one split (files: from sartco.instances.storage.load_dataset)."""
    name = kind.dataset_file(split)
    if name not in files:
        sys.exit(f"instancegenerator: {dataset / name}: missing (generate the dataset first: sartco generate)")
    return files[name]


def spread(items: list, n: int | None) -> list:
    """n items evenly spread over the list (all when n is None or too large)."""
    if n is None or n >= len(items):
        return list(items)
    return [items[i * len(items) // n] for i in range(n)]


class CobotDescribeInstanceGenerator(InstanceGenerator):

    def __init__(self):
        super().__init__(str(GAME_DIR))

    def on_generate(self, seed: int, dataset: Path = REPO / "instances" / "v1", examples: int = 5,
                    per_experiment: int | None = None, questions: int = DEFAULT_QUESTIONS,
                    corrections: int = DEFAULT_CORRECTIONS, modes: tuple[str, ...] = MODES, **kwargs):
        self.source = dataset
        manifest, files = load_dataset(dataset)
        self.instances["dataset"] = {"version": manifest["version"], "seed": manifest["seed"],
                                     "source": manifest["source"], "split": "test"}
        self.instances["seed"] = seed
        game_id = 0
        for mode in MODES:
            for kind in BOARD_KINDS:  # the builder's task: the paper's for model-written instructions
                task = DESCRIBED_TASK[kind.board]
                boards = spread(split_records(dataset, files, kind, "test"), per_experiment)
                if mode not in modes:  # another entry's file: its ids stay taken, so ids are unique across files
                    game_id += len(boards)
                    continue
                experiment = self.add_experiment(kind.experiment if mode == "oneshot" else f"{kind.experiment}_{mode}")
                experiment.update(DescribeExperiment(board_type=kind.board, object_type=kind.object, task=task,
                                                     source="describer", split="test", dataset=manifest["version"],
                                                     dataset_seed=manifest["seed"], examples=examples,
                                                     example_seed=seed))
                if mode != "oneshot":  # oneshot experiments keep the fields they always had
                    experiment.update(mode=mode, questions=questions if "clarify" in mode else 0,
                                      corrections=corrections if "correct" in mode else 0)
                pool = split_records(dataset, files, kind, "train")
                for record in boards:
                    shots = select_examples(record, pool, k=examples, rng=seed)
                    prompt = builder_prompt(record, task, shots, instruction=INSTRUCTION_SLOT)
                    if "clarify" in mode:
                        prompt = f"{prompt.rstrip()}\n\n{clarify_note(questions)}\n"
                    self.add_game_instance(experiment, game_id).update(DescribeEpisode(
                        game_id=game_id, **board_fields(record, task), example_ids=[r["id"] for r in shots],
                        describer_prompt=describer_prompt(record), builder_prompt=prompt,
                        template_instruction=instruction_text(record, task, "template"), record=record))
                    game_id += 1


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--dataset", type=Path, default=REPO / "instances" / "v1", help="dataset folder")
    parser.add_argument("--seed", type=int, default=42, help="seed of the in-context example choice")
    parser.add_argument("--examples", type=int, default=5, help="in-context examples per prompt (0..10)")
    parser.add_argument("--questions", type=int, default=DEFAULT_QUESTIONS,
                        help=f"questions the builder may ask in the clarify modes (default {DEFAULT_QUESTIONS})")
    parser.add_argument("--corrections", type=int, default=DEFAULT_CORRECTIONS,
                        help=f"corrections the describer may send in the correct modes (default {DEFAULT_CORRECTIONS})")
    parser.add_argument("--slice", type=int, default=None, metavar="N",
                        help="also write in/instances_slice.json with N episodes per experiment")
    args = parser.parse_args(argv)
    if not (args.dataset / "manifest.json").is_file():
        parser.error(f"--dataset {args.dataset}: no manifest.json (not a dataset folder)")
    if args.slice is not None and args.slice < 1:
        parser.error("--slice must be at least 1")
    if args.questions < 0 or args.corrections < 0:
        parser.error("--questions and --corrections must be at least 0")
    settings = dict(seed=args.seed, dataset=args.dataset, examples=args.examples, questions=args.questions,
                    corrections=args.corrections)
    try:
        for name, modes in ENTRY_FILES.items():
            print(CobotDescribeInstanceGenerator().generate(f"{name}.json", modes=modes, **settings))
            if args.slice is not None:
                print(CobotDescribeInstanceGenerator().generate(f"{name}_slice.json", modes=modes,
                                                                per_experiment=args.slice, **settings))
    except UserError as exc:
        print(f"instancegenerator: {exc}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
