"""cobot_describe's instance files (`sartco instances describe`), from a generated dataset's test split.

One experiment per board kind, every test board of the dataset one episode, named as every
experiment of both games (sartco.dataset.experiment_name: <cell>_<task>_<source>[_<variant>]; the
task is DESCRIBED_TASK's, the source "describer"):
  sb_so_optimal_function_describer   simple boards (simple objects); the builder writes the optimal
                                     function (the paper's single-turn task of model-written instructions)
  rb_so_repetition_describer         regular boards of simple objects; the builder gets the object
  rb_co_repetition_describer         function and writes the repetition code (of complex objects)
The builder's prompt is cobot_instruct's (sartco.instances.prompts.builder_prompt)
with --examples in-context examples from the dataset's train split (select_examples, seeded by
--seed); the instruction slot is filled during the game with what the describer wrote. The file
records the dataset version and seed (`dataset`) and the generator's seed (`seed`).

Each board kind is played in every mode of sartco.games.describe.dialogue.MODES: `oneshot` (the three
experiments above, no variant) in in/instances.json, the game entry `cobot_describe` (the paper's
one-shot game: its clemscore means that alone), and the mode as the variant, `<name>_clarify`,
`<name>_correct`, `<name>_clarify_correct` (experiment fields `mode`, `questions` K = --questions,
`corrections` R = --corrections; the same boards and prompts, the builder's prompt of a clarify
mode ends with the paragraph on questions, sartco.games.describe.dialogue.clarify_note) in
in/instances_dialogue.json, the entry `cobot_describe_dialogue`. game_id counts from 0 in each
experiment, as in every instance file: an episode is (game, experiment, game_id), and the same
board has the same game_id in every mode.

in/instances_smoke.json holds the first --smoke episodes (2) of each experiment of in/instances.json
(the same episodes, the same game_ids): `clem run -g cobot_describe -m MODEL -i instances_smoke`, a
first try of the game, as cobot_instruct's smoke file.

--slice N also writes in/instances_slice.json and in/instances_dialogue_slice.json with N episodes
per experiment, spread over the split, for a smoke run with a local model:
`clem run -g cobot_describe -m MODEL -i instances_slice`.
"""
from __future__ import annotations

from argparse import Namespace
from pathlib import Path

from sartco.clem.core.instance_files import InstanceGenerator, board_fields, records, spread, stamp, written
from sartco.dataset import BOARD_KINDS, DESCRIBED_TASK, experiment_name
from sartco.episode import DescribeEpisode, DescribeExperiment
from sartco.instances.examples import select_examples
from sartco.instances.prompts import builder_prompt, describer_prompt, instruction_text
from sartco.instances.storage import loaded_dataset

from .dialogue import INSTRUCTION_SLOT, MODES, clarify_note

ONESHOT = ("oneshot",)
DIALOGUE = tuple(m for m in MODES if m != "oneshot")
SOURCE = "describer"  # who writes the builder's instructions


def first(items: list, n: int | None) -> list:
    """The first n items (all when n is None)."""
    return list(items[:n])


def modes_file(gen: InstanceGenerator, seed: int, dataset: Path, examples: int, per_experiment: int | None,
               questions: int, corrections: int, modes: tuple[str, ...], pick=spread):
    """The experiments of `modes` (ONESHOT or DIALOGUE), game_id counted from 0 in each;
    per_experiment boards of the split, chosen by `pick` (spread over it, or the first)."""
    gen.source = dataset
    manifest, files = loaded_dataset(dataset)
    gen.instances["dataset"] = {"version": manifest["version"], "seed": manifest["seed"],
                                "source": manifest["source"], "split": "test"}
    gen.instances["seed"] = seed
    for mode in modes:
        for kind in BOARD_KINDS:  # the builder's task: the paper's for model-written instructions
            task = DESCRIBED_TASK[kind.board]
            boards = pick(records(dataset, files, kind, "test"), per_experiment)
            experiment = gen.add_experiment(experiment_name(kind, task, SOURCE, None if mode == "oneshot" else mode))
            experiment.update(DescribeExperiment(board_type=kind.board, object_type=kind.object, task=task,
                                                 source=SOURCE, split="test", dataset=manifest["version"],
                                                 dataset_seed=manifest["seed"], examples=examples,
                                                 example_seed=seed))
            if mode != "oneshot":  # oneshot experiments keep the fields they always had
                experiment.update(mode=mode, questions=questions if "clarify" in mode else 0,
                                  corrections=corrections if "correct" in mode else 0)
            pool = records(dataset, files, kind, "train")
            for game_id, record in enumerate(boards):
                shots = select_examples(record, pool, k=examples, rng=seed)
                prompt = builder_prompt(record, task, shots, instruction=INSTRUCTION_SLOT)
                if "clarify" in mode:
                    prompt = f"{prompt.rstrip()}\n\n{clarify_note(questions)}\n"
                gen.add_game_instance(experiment, game_id).update(DescribeEpisode(
                    game_id=game_id, **board_fields(record, task), example_ids=[r["id"] for r in shots],
                    describer_prompt=describer_prompt(record), builder_prompt=prompt,
                    template_instruction=instruction_text(record, task, "template"), record=record))


class DescribeFile(InstanceGenerator):
    """One cobot_describe instance file: the experiments of modes_file."""

    def on_generate(self, seed: int, **kwargs):
        modes_file(self, seed, **kwargs)
        stamp(self)


def write(gen: InstanceGenerator, name: str, seed: int, **kwargs) -> str:
    """Write in/<name> through gen (on_generate(seed, **kwargs)), say what it holds (as cobot_instruct's)."""
    return written(gen, gen.generate(name, seed=seed, **kwargs))


def _files(options: Namespace, modes: tuple[str, ...], per_experiment: int | None, pick=spread) -> dict:
    """modes_file's arguments for a file of `modes` (per_experiment: a slice's N, None for all; pick:
    spread over the split or the first)."""
    return dict(dataset=options.dataset, examples=options.examples, per_experiment=per_experiment,
                questions=options.questions, corrections=options.corrections, modes=modes, pick=pick)


# one function per file: (options, game folder) -> the path written
def instances(options: Namespace, game_dir: Path) -> str:
    return write(DescribeFile(str(game_dir)), "instances.json", options.seed, **_files(options, ONESHOT, None))


def instances_smoke(options: Namespace, game_dir: Path) -> str:
    return write(DescribeFile(str(game_dir)), "instances_smoke.json", options.seed, **_files(options, ONESHOT, options.smoke, first))


def instances_slice(options: Namespace, game_dir: Path) -> str:
    return write(DescribeFile(str(game_dir)), "instances_slice.json", options.seed, **_files(options, ONESHOT, options.slice))


def instances_dialogue(options: Namespace, game_dir: Path) -> str:
    return write(DescribeFile(str(game_dir)), "instances_dialogue.json", options.seed, **_files(options, DIALOGUE, None))


def instances_dialogue_slice(options: Namespace, game_dir: Path) -> str:
    return write(DescribeFile(str(game_dir)), "instances_dialogue_slice.json", options.seed, **_files(options, DIALOGUE, options.slice))
