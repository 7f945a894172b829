"""cobot_instruct's instance files, one function per file (`sartco instances instruct...`,
docs/ARCHITECTURE.md "Datasets"). Each is played under its own clemgame.json entry (its own game
name, so its results, and clem eval's clemscore, never mix with the others):

  instances.json            cobot_instruct: the template cells of the paper's Table 3, test split
                            (the leaderboard number means these and nothing else);
  instances_ablations.json  cobot_instruct_ablations: val split, 0..10 in-context examples and
                            each prompt section removed;
  instances_feedback.json   cobot_instruct_feedback: the Table 3 template cells, `<cell>_feedback`,
                            with `attempts` (the first attempt plus up to N - 1 repairs after
                            execution feedback, sartco.clem.core.feedback) and `feedback_of` (the cell);
  instances_smoke.json      the first --smoke episodes of each Table 3 template cell (the same
                            episodes as in instances.json): `clem run -g cobot_instruct -i instances_smoke`;
  instances_published.json  cobot_instruct_published (gitignored: it embeds the published texts),
                            from the imported published data (`sartco import ../shared/sartco-data/published
                            --out instances/published`): the human- and model-written cells of Table 3;
  instances_published_feedback.json  cobot_instruct_published_feedback (gitignored);
  instances_train.json      the train split, for training (sartco.games.instruct.training): one experiment per
                            cell, `<cell>_train`, over the first --train-episodes train boards (0: all);
                            the examples from the same pool, never the episode's own board;
  instances_describers.json from a `sartco import-instructions` dataset: one experiment per
                            describer model and board kind, the builder task of cobot_describe;
  instances_paper.json      cobot_instruct_paper (gitignored): the paper protocol, every Table 3 cell
                            on the published test files (read from ../shared at generation time),
                            named paper_<cell>_<task>_<source>, each recording protocol "paper", its
                            variant, where its examples came from and the paper's generation settings
                            (temperature 0, 250 tokens: `clem run -t 0 -l 250`);
  instances_fresh.json      cobot_instruct_fresh (gitignored; sartco.games.instruct.fresh): each template
                            cell's published test boards beside as many fresh boards of a seed.

Experiment names: sartco.dataset.experiment_name (variants: examples_<k>, without_<section>, feedback,
train, published, fresh<SEED>; paper_ prefixed). Episodes: instruct_episode; InstructGenerator: the base.
In-context examples always come from the generated dataset's train split (the published data has
no simple-board train split). game_id counts from 0 in each experiment. Each experiment and the file
record the dataset (dataset_info: version, source, seed, path) and this generator's seed.
"""
from __future__ import annotations

import os
from argparse import Namespace
from pathlib import Path
from typing import Callable

from sartco.clem.core.instance_files import InstanceGenerator, board_fields, records, stamp, written
from sartco.dataset import (BOARD_KINDS, DESCRIBED_TASK, REGULAR_COMPLEX, REGULAR_SIMPLE, SIMPLE, BoardKind,
                            board_kind, experiment_name)
from sartco.episode import InstructEpisode, InstructExperiment
from sartco.errors import UserError
from sartco.instances.examples import MAX_EXAMPLES, select_examples
from sartco.instances.prompts import SECTIONS, builder_prompt, builder_turn, gold_code, instruction_text
from sartco.instances.storage import loaded_dataset
from sartco.settings import workspace

DEFAULT_PUBLISHED = workspace() / "instances" / "published"   # `sartco import ../shared/sartco-data/published --out ...`
FEEDBACK = "feedback"           # the variant of the feedback experiments: <cell>_<task>_<source>_feedback
FEEDBACK_SUFFIX = f"_{FEEDBACK}"  # and of their files: instances_feedback.json

# the cells of the paper's Table 3: (board kind, task, sources from the generated data, from the published data)
CELLS = [
    (SIMPLE, "first_order", ["template"], []),
    (SIMPLE, "sequence_function", ["template"], ["human"]),
    (SIMPLE, "optimal_function", ["template"], ["human", "codellama", "gpt4", "claude"]),
    (REGULAR_SIMPLE, "repetition", ["template"], ["human", "codellama", "gpt4", "claude"]),
    (REGULAR_COMPLEX, "repetition", ["template"], ["human"]),
]


def instruct_episode(record: dict, task: str, source: str, examples: list[dict], sections=SECTIONS) -> InstructEpisode:
    """One cobot_instruct game instance: the board's fields (every game's: board_fields), what the
    builder is told (the prompt with `examples` and `sections`; multi-turn: one message per later
    step), and what `mock` answers per turn."""
    code = record["code"]
    if task == "first_order":
        steps = instruction_text(record, task, source)
        turns = [builder_prompt(record, task, examples, sections, source, step=0)]
        turns += [builder_turn(record, k, source) for k in range(1, len(steps))]
        instructions, gold_turns = list(steps), list(code["first_order"]["steps"])
    else:
        turns = [builder_prompt(record, task, examples, sections, source)]
        instructions = [instruction_text(record, task, source)]
        gold_turns = [gold_code(record, task)]
    return {**board_fields(record, task), "source": source, "turns": turns, "instructions": instructions,
            "gold_turns": gold_turns, "examples": [ex["id"] for ex in examples]}


class InstructGenerator(InstanceGenerator):
    """The base of cobot_instruct's instance generators (InstructFile, and fresh.FreshInstanceGenerator):
    one experiment per cell, with or without execution feedback, and its episodes from board
    records, each with its in-context examples, game_id counted from 0 in each experiment."""

    def __init__(self, game_dir: str, feedback_attempts: int | None = None):
        """feedback_attempts: None for the paper's experiments; N >= 2 for the feedback experiments
        (the Table 3 cells only, named <cell>_feedback, N attempts per episode)."""
        super().__init__(game_dir)
        self.feedback_attempts = feedback_attempts

    def experiment(self, kind: BoardKind, task: str, source: str, split: str, dataset: dict,
                   ablation: dict | None = None, variant: str | None = None, **extra):
        """The experiment experiment_name(kind, task, source, variant) (with feedback: its
        _feedback variant); extra: more experiment fields (before game_instances)."""
        name, feedback = experiment_name(kind, task, source, variant), {}
        if self.feedback_attempts is not None:
            feedback = {"attempts": self.feedback_attempts, "feedback_of": name}
            name = experiment_name(kind, task, source, variant, FEEDBACK)
        exp = self.add_experiment(name)
        exp.update(InstructExperiment(board_type=kind.board, object_type=kind.object, task=task, source=source,
                                      split=split, ablation=ablation, **feedback, dataset=dataset), **extra)
        exp.move_to_end("game_instances")
        return exp

    def add_episodes(self, exp, items, task, source, pool, seed, k, sections=SECTIONS):
        for game_id, record in enumerate(items):
            examples = select_examples(record, pool, k, seed) if "examples" in sections else []
            inst = self.add_game_instance(exp, game_id)
            inst.update(instruct_episode(record, task, source, examples, sections))


class InstructFile(InstructGenerator):
    """One cobot_instruct instance file: on_generate runs the file's build function (table3,
    ablations, train, published, described, paper), which fills `instances` (through experiment /
    add_episodes / add_experiment / add_game_instance) and sets `source`, the input an error line
    names when no episode came out of it."""

    def __init__(self, game_dir: str | Path, build: Callable, feedback_attempts: int | None = None):
        super().__init__(str(game_dir), feedback_attempts)
        self.build = build

    def on_generate(self, seed: int, **kwargs):
        self.build(self, seed, **kwargs)
        stamp(self)


def write(gen: InstanceGenerator, name: str, seed: int, **kwargs) -> str:
    """Write in/<name> through gen (on_generate(seed, **kwargs)), say what it holds (as cobot_describe's)."""
    return written(gen, gen.generate(name, seed=seed, **kwargs))


def dataset_info(manifest: dict, path: Path, seed: int, n_examples: int, examples_from: dict | None = None) -> dict:
    """What a cobot_instruct instance file records about its dataset (examples_from: the dataset
    of the in-context examples when it is another one)."""
    info = {"version": manifest["version"], "source": manifest["source"], "seed": manifest.get("seed"),
            "path": os.path.relpath(path, workspace())}
    if examples_from is not None:
        info["examples_from"] = examples_from
    return {**info, "generator_seed": seed, "n_examples": n_examples}


def _generated(gen: InstructFile, seed: int, dataset_dir: Path, n_examples: int):
    """The generated dataset's files, the train pools of the in-context examples, and the
    dataset as the file records it (the file's `dataset` until a build names another one)."""
    manifest, files = loaded_dataset(dataset_dir)
    info = gen.instances["dataset"] = dataset_info(manifest, dataset_dir, seed, n_examples)
    return files, {kind: records(dataset_dir, files, kind, "train") for kind in BOARD_KINDS}, info


def table3(gen: InstructFile, seed: int, dataset_dir: Path, n_examples: int, per_experiment: int | None = None):
    """The template cells of Table 3 (test split; per_experiment: the first N episodes of each)."""
    gen.source = dataset_dir
    files, pools, info = _generated(gen, seed, dataset_dir, n_examples)
    for kind, task, sources, _ in CELLS:
        for source in sources:
            exp = gen.experiment(kind, task, source, "test", info)
            items = records(dataset_dir, files, kind, "test")[:per_experiment]
            gen.add_episodes(exp, items, task, source, pools[kind], seed, n_examples)


def ablations(gen: InstructFile, seed: int, dataset_dir: Path, n_examples: int, episodes: int):
    """Every template cell on the first `episodes` val boards: 0..MAX_EXAMPLES examples, and each
    prompt section left out."""
    gen.source = dataset_dir
    files, pools, info = _generated(gen, seed, dataset_dir, n_examples)
    for kind, task, _, _ in CELLS:
        val = records(dataset_dir, files, kind, "val")[:episodes]
        for k in range(MAX_EXAMPLES + 1):
            exp = gen.experiment(kind, task, "template", "val", info, {"kind": "examples", "value": k},
                                 variant=f"examples_{k}")
            gen.add_episodes(exp, val, task, "template", pools[kind], seed, k)
        for section in SECTIONS:
            kept = tuple(s for s in SECTIONS if s != section)
            exp = gen.experiment(kind, task, "template", "val", info, {"kind": "without", "value": section},
                                 variant=f"without_{section}")
            gen.add_episodes(exp, val, task, "template", pools[kind], seed, n_examples, kept)


def train(gen: InstructFile, seed: int, dataset_dir: Path, n_examples: int, episodes: int):
    """Every template cell on the first `episodes` train boards (0: all)."""
    gen.source = dataset_dir
    _, pools, info = _generated(gen, seed, dataset_dir, n_examples)
    for kind, task, _, _ in CELLS:
        exp = gen.experiment(kind, task, "template", "train", info, variant="train")
        gen.add_episodes(exp, pools[kind][:episodes or None], task, "template", pools[kind], seed, n_examples)


def published(gen: InstructFile, seed: int, dataset_dir: Path, n_examples: int, published_dir: Path):
    """The human- and model-written cells of Table 3 from the imported published data."""
    gen.source = published_dir
    _, pools, info = _generated(gen, seed, dataset_dir, n_examples)
    pub_manifest, pub_files = loaded_dataset(published_dir)
    pub_info = gen.instances["dataset"] = dataset_info(pub_manifest, published_dir, seed, n_examples,
                                                       examples_from=info)
    for kind, task, _, sources in CELLS:
        for source in sources:
            items = [r for r in records(published_dir, pub_files, kind, "test") if source in r["instructions"]]
            exp = gen.experiment(kind, task, source, "test", pub_info)
            gen.add_episodes(exp, items, task, source, pools[kind], seed, n_examples)


def described(gen: InstructFile, seed: int, dataset_dir: Path, n_examples: int, describers_dir: Path):
    """One experiment per describer model (an instruction source of the manifest) and board kind,
    named <cell>_<task>_<model>, with the builder task cobot_describe gives (DESCRIBED_TASK)."""
    gen.source = describers_dir
    _, pools, info = _generated(gen, seed, dataset_dir, n_examples)
    manifest, files = loaded_dataset(describers_dir)
    if manifest.get("source") != "describer":
        raise UserError(f"{describers_dir}: not a describer dataset (manifest source {manifest.get('source')!r})")
    d_info = gen.instances["dataset"] = dataset_info(manifest, describers_dir, seed, n_examples, examples_from=info)
    unplayed = [experiment_name(kind, DESCRIBED_TASK[kind.board], "describer") for kind in BOARD_KINDS
                if kind.dataset_file("test") not in files]
    if unplayed:  # a describer run of only some of cobot_describe's experiments
        raise UserError(f"{describers_dir}: the describer run played no episode of {', '.join(unplayed)}: play "
                        f"{'each with' if len(unplayed) > 1 else 'it with'} `clem run -g cobot_describe -e EXPERIMENT "
                        f"-m MODEL -r RESULTS` into the describer's results, then `sartco import-instructions -r "
                        f"RESULTS --out {describers_dir}` again")
    for source in manifest["config"]["instruction_sources"]:
        for kind in BOARD_KINDS:
            task = DESCRIBED_TASK[kind.board]
            items = [r for r in records(describers_dir, files, kind, "test") if source in r["instructions"]]
            if items:
                exp = gen.experiment(kind, task, source, "test", d_info)
                gen.add_episodes(exp, items, task, source, pools[kind], seed, n_examples)


def paper(gen: InstructFile, seed: int, dataset_dir: Path, published_dir: Path | None = None):
    """The paper protocol (sartco.paper.episodes.build_episodes) on the published test files (from
    ../shared), one experiment per Table 3 cell, paper_<cell>_<task>_<source>. seed: unused (the
    paper's examples have their own)."""
    from .paper import experiment_fields, instance_fields
    from sartco.paper import PROTOCOL
    from sartco.paper import episodes as paper_episodes

    published_dir = gen.source = published_dir or paper_episodes.DEFAULT_PUBLISHED
    cells: dict[tuple, list[dict]] = {}
    for ep in paper_episodes.build_episodes(published_dir=published_dir, generated_dir=dataset_dir):
        cells.setdefault((ep.file, ep.variant), []).append(ep.to_json())
    gen.instances["dataset"] = {"protocol": PROTOCOL, "published": os.path.relpath(published_dir, workspace()),
                                "generated": os.path.relpath(dataset_dir, workspace())}
    for episodes in cells.values():
        cell = episodes[0]["cell"]
        kind = board_kind(cell["board"], cell["object"])
        exp = gen.add_experiment(f"{PROTOCOL}_{experiment_name(kind, cell['task'], cell['source'])}")
        exp.update(experiment_fields(episodes[0]))
        exp.move_to_end("game_instances")
        for game_id, episode in enumerate(episodes):
            gen.add_game_instance(exp, game_id).update(instance_fields(episode))


# one function per file: (options, game folder) -> the path written
def instances(options: Namespace, game_dir: Path) -> str:
    return write(InstructFile(game_dir, table3), "instances.json", options.seed, dataset_dir=options.dataset, n_examples=options.examples)


def instances_ablations(options: Namespace, game_dir: Path) -> str:
    return write(InstructFile(game_dir, ablations), "instances_ablations.json", options.seed, dataset_dir=options.dataset,
                 n_examples=options.examples, episodes=options.ablation_episodes)


def instances_feedback(options: Namespace, game_dir: Path) -> str:
    return write(InstructFile(game_dir, table3, options.attempts), f"instances{FEEDBACK_SUFFIX}.json", options.seed,
                 dataset_dir=options.dataset, n_examples=options.examples)


def instances_smoke(options: Namespace, game_dir: Path) -> str:
    return write(InstructFile(game_dir, table3), "instances_smoke.json", options.seed, dataset_dir=options.dataset,
                 n_examples=options.examples, per_experiment=options.smoke)


def instances_published(options: Namespace, game_dir: Path) -> str:
    return write(InstructFile(game_dir, published), "instances_published.json", options.seed, dataset_dir=options.dataset,
                 n_examples=options.examples, published_dir=options.published or DEFAULT_PUBLISHED)


def instances_published_feedback(options: Namespace, game_dir: Path) -> str:
    return write(InstructFile(game_dir, published, options.attempts), f"instances_published{FEEDBACK_SUFFIX}.json",
                 options.seed, dataset_dir=options.dataset, n_examples=options.examples, published_dir=options.published or DEFAULT_PUBLISHED)


def instances_train(options: Namespace, game_dir: Path) -> str:
    return write(InstructFile(game_dir, train), "instances_train.json", options.seed, dataset_dir=options.dataset,
                 n_examples=options.examples, episodes=options.train_episodes)


def instances_describers(options: Namespace, game_dir: Path) -> str:
    return write(InstructFile(game_dir, described), "instances_describers.json", options.seed, dataset_dir=options.dataset,
                 n_examples=options.examples, describers_dir=options.describers)


def instances_paper(options: Namespace, game_dir: Path) -> str:
    return write(InstructFile(game_dir, paper), "instances_paper.json", options.seed, dataset_dir=options.dataset, published_dir=options.paper_data)

