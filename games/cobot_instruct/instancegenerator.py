"""Build the episodes of cobot_instruct from SARTCo datasets (docs/ARCHITECTURE.md, "Datasets").

    python games/cobot_instruct/instancegenerator.py        # in/instances.json, instances_ablations.json,
                                                            # instances_feedback.json, instances_smoke.json
    python games/cobot_instruct/instancegenerator.py --published instances/published
                                               # in/instances_published.json + ..._published_feedback.json
    python games/cobot_instruct/instancegenerator.py --protocol paper   # in/instances_paper.json
    python games/cobot_instruct/instancegenerator.py --fresh SEED [--fresh-episodes N]
                                               # in/instances_fresh.json (published vs fresh boards, sartco.clem.instruct.fresh)
    python games/cobot_instruct/instancegenerator.py --train [--train-episodes N]
                                               # in/instances_train.json (training, sartco.clem.instruct.training)

One file per kind of run, each played under its own clemgame.json entry (its own game name, so
its results, and clem eval's clemscore, never mix with the others):
  in/instances.json            cobot_instruct: the template cells of the paper's Table 3, test split
                               (the leaderboard number means these and nothing else);
  in/instances_ablations.json  cobot_instruct_ablations: val split, 0..10 in-context examples and
                               each prompt section removed;
  in/instances_feedback.json   cobot_instruct_feedback: the Table 3 template cells with execution
                               feedback and repair (beyond the paper, below);
  in/instances_smoke.json      the first --smoke (2) episodes of each Table 3 template cell, the same
                               episodes as in instances.json: `clem run -g cobot_instruct -i instances_smoke`;
  in/instances_published.json  cobot_instruct_published (gitignored: it embeds the published texts),
                               from the imported published data (`sartco import
                               ../shared/sartco-data/published --out instances/published`): the
                               human-written and model-written cells of Table 3 (test split);
  in/instances_published_feedback.json  cobot_instruct_published_feedback (gitignored).
The committed files are written from the generated dataset (default instances/v1).

Experiment names: <board>_<object>_<task>_<source>[_<ablation>], board sb|rb (simple|regular
board), object so|co (simple|complex object), task first_order | sequence_function |
optimal_function | repetition, source template | human | codellama | gpt4 | claude; ablations
end in _examples_<k> or _without_<section>. In-context examples always come from the
generated dataset's train split (the published data has no simple-board train split) and show
template instructions with gold code of the task's style (sartco.instances.examples/prompts).
Each experiment and the file record the dataset version, source and seed, and this generator's seed.

Train split (for training, never mixed into the test cells): in/instances_train.json (gitignored:
derived, about 8 kB an episode) holds one experiment per Table 3 cell, `<cell>_train` (template
instructions, split "train"), over the dataset's train boards (all, or the first N of each
cell); their in-context examples come from the same train pool, never the episode's own board
(select_examples skips its combo and location).

in/instances_paper.json (gitignored: it embeds the authors' templates and the published texts) is
the paper protocol (game entry cobot_instruct_paper): sartco.paper.episodes.build_episodes, every
Table 3 cell on the published test files (read from ../shared at generation time; examples from
the published rb_so_train or, where the authors' training file was never published, from the
generated dataset's train split), one experiment per cell, named paper_<board>_<object>_<task>_<source>
as above, each recording protocol "paper", its variant, where its examples came from and the
paper's generation settings (temperature 0, 250 tokens: run it with `clem run -t 0 -l 250`).

Feedback experiments (beyond the paper, issue 7): one experiment per Table 3 cell,
`<cell>_feedback`, with the same episodes and the fields `attempts` (N, default 3: the first
attempt plus up to N - 1 repairs after execution feedback, sartco.clem.core.feedback) and
`feedback_of` (the cell's name).
    clem run -g cobot_instruct_feedback -m mock [-e sb_so_first_order_template_feedback]
"""
from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path

from sartco.clem.core.instance_values import InstanceGenerator
from sartco.clem.instruct.fresh import FreshInstanceGenerator
from sartco.clem.instruct.instruct_generator import FEEDBACK_SUFFIX, InstructGenerator
from sartco.dataset import BOARD_KINDS, DESCRIBED_TASK, REGULAR_COMPLEX, REGULAR_SIMPLE, SIMPLE, BoardKind, board_kind
from sartco.errors import UserError
from sartco.instances.examples import MAX_EXAMPLES
from sartco.instances.storage import load_dataset
from sartco.instances.prompts import SECTIONS

GAME_DIR = Path(__file__).resolve().parent
REPO = GAME_DIR.parents[1]
N_EXAMPLES = 5          # in-context examples in the Table 3 experiments
ABLATION_EPISODES = 10  # episodes per ablation experiment (val split)
FEEDBACK_ATTEMPTS = 3   # attempts per episode in the feedback experiments
SMOKE_EPISODES = 2      # episodes per Table 3 cell in in/instances_smoke.json

# the cells of the paper's Table 3: (board kind, task, sources from the generated data, from the published data)
CELLS = [
    (SIMPLE, "first_order", ["template"], []),
    (SIMPLE, "sequence_function", ["template"], ["human"]),
    (SIMPLE, "optimal_function", ["template"], ["human", "codellama", "gpt4", "claude"]),
    (REGULAR_SIMPLE, "repetition", ["template"], ["human", "codellama", "gpt4", "claude"]),
    (REGULAR_COMPLEX, "repetition", ["template"], ["human"]),
]


def dataset_info(manifest: dict, path: Path, seed: int, n_examples: int, examples_from: dict | None = None) -> dict:
    """What an instance file records about its dataset (examples_from: the dataset of the
    in-context examples when it is another one)."""
    info = {"version": manifest["version"], "source": manifest["source"], "seed": manifest.get("seed"),
            "path": os.path.relpath(path, REPO)}
    if examples_from is not None:
        info["examples_from"] = examples_from
    return {**info, "generator_seed": seed, "n_examples": n_examples}


def records(files: dict, kind: BoardKind, split: str) -> list[dict]:
    name = kind.dataset_file(split)
    if name not in files:
        raise UserError(f"dataset has no file {name}")
    return files[name]


class PaperInstanceGenerator(InstanceGenerator):
    """in/instances_paper.json: the paper protocol's episodes, one experiment per Table 3 cell."""

    def __init__(self):
        super().__init__(str(GAME_DIR))

    def on_generate(self, seed: int, dataset_dir: Path, published_dir: Path | None = None):
        from sartco.clem.paper.game import experiment_fields, instance_fields
        from sartco.paper import PROTOCOL
        from sartco.paper.episodes import DEFAULT_PUBLISHED, build_episodes

        published_dir = self.source = published_dir or DEFAULT_PUBLISHED
        cells: dict[tuple, list[dict]] = {}
        for ep in build_episodes(published_dir=published_dir, generated_dir=dataset_dir):
            cells.setdefault((ep.file, ep.variant), []).append(ep.to_json())
        self.instances["dataset"] = {"protocol": PROTOCOL, "published": os.path.relpath(published_dir, REPO),
                                     "generated": os.path.relpath(dataset_dir, REPO)}
        for episodes in cells.values():
            cell = episodes[0]["cell"]
            kind = board_kind(cell["board"], cell["object"])
            exp = self.add_experiment(f"{PROTOCOL}_{kind.cell}_{cell['task']}_{cell['source']}")
            exp.update(experiment_fields(episodes[0]))
            exp.move_to_end("game_instances")
            for game_id, episode in enumerate(episodes):
                self.add_game_instance(exp, game_id).update(instance_fields(episode))


class CobotInstructInstanceGenerator(InstructGenerator):
    """experiment() and add_episodes(): sartco.clem.instruct.instruct_generator."""

    def __init__(self, feedback_attempts: int | None = None):
        super().__init__(str(GAME_DIR), feedback_attempts)

    def on_generate(self, seed: int, dataset_dir: Path, published_dir: Path | None = None,
                    n_examples: int = N_EXAMPLES, ablation_episodes: int = ABLATION_EPISODES,
                    describers_dir: Path | None = None, part: str = "cells", per_experiment: int | None = None,
                    train_episodes: int = 0):
        """part: "cells" (the Table 3 cells, test split; per_experiment: only the first episodes of
        each, a smoke file) "ablations" (val split) or "train" (the train split, for training; train_episodes: the
        first N boards of each cell, 0: all)."""
        self.source = describers_dir or published_dir or dataset_dir
        manifest, files = load_dataset(dataset_dir)
        info = dataset_info(manifest, dataset_dir, seed, n_examples)
        self.instances["dataset"] = info
        pools = {kind: records(files, kind, "train") for kind in BOARD_KINDS}
        if describers_dir is not None:
            self.add_described(describers_dir, info, pools, seed, n_examples)
            return
        if part == "train":
            for kind, task, _, _ in CELLS:
                exp = self.experiment(f"{kind.cell}_{task}_template_train", kind, task, "template", "train", info)
                self.add_episodes(exp, pools[kind][:train_episodes or None], task, "template", pools[kind], seed,
                                  n_examples)
            return
        if part == "ablations":
            for kind, task, _, _ in CELLS:
                val = records(files, kind, "val")[:ablation_episodes]
                for k in range(MAX_EXAMPLES + 1):
                    exp = self.experiment(f"{kind.cell}_{task}_template_examples_{k}", kind, task, "template", "val",
                                          info, {"kind": "examples", "value": k})
                    self.add_episodes(exp, val, task, "template", pools[kind], seed, k)
                for section in SECTIONS:
                    kept = tuple(s for s in SECTIONS if s != section)
                    exp = self.experiment(f"{kind.cell}_{task}_template_without_{section}", kind, task, "template",
                                          "val", info, {"kind": "without", "value": section})
                    self.add_episodes(exp, val, task, "template", pools[kind], seed, n_examples, kept)
            return
        if published_dir is None:
            for kind, task, sources, _ in CELLS:
                for source in sources:
                    exp = self.experiment(f"{kind.cell}_{task}_{source}", kind, task, source, "test", info)
                    items = records(files, kind, "test")[:per_experiment]
                    self.add_episodes(exp, items, task, source, pools[kind], seed, n_examples)
            return
        pub_manifest, pub_files = load_dataset(published_dir)
        pub_info = dataset_info(pub_manifest, published_dir, seed, n_examples, examples_from=info)
        self.instances["dataset"] = pub_info
        for kind, task, _, sources in CELLS:
            for source in sources:
                items = [r for r in records(pub_files, kind, "test") if source in r["instructions"]]
                exp = self.experiment(f"{kind.cell}_{task}_{source}", kind, task, source, "test", pub_info)
                self.add_episodes(exp, items[:per_experiment], task, source, pools[kind], seed, n_examples)

    def add_described(self, describers_dir: Path, info: dict, pools: dict, seed: int, n_examples: int):
        """Experiments from a `sartco import-instructions` dataset: one per describer model (an
        instruction source of its manifest) and board kind, named <board>_<task>_<model>, with the
        builder task cobot_describe gives its builder (DESCRIBED_TASK)."""
        manifest, files = load_dataset(describers_dir)
        if manifest.get("source") != "describer":
            raise UserError(f"{describers_dir}: not a describer dataset (manifest source {manifest.get('source')!r})")
        d_info = dataset_info(manifest, describers_dir, seed, n_examples, examples_from=info)
        self.instances["dataset"] = d_info
        for source in manifest["config"]["instruction_sources"]:
            for kind in BOARD_KINDS:
                task = DESCRIBED_TASK[kind.board]
                items = [r for r in records(files, kind, "test") if source in r["instructions"]]
                if items:
                    exp = self.experiment(f"{kind.cell}_{task}_{source}".replace("/", "_"), kind, task, source,
                                          "test", d_info)
                    self.add_episodes(exp, items, task, source, pools[kind], seed, n_examples)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--dataset", type=Path, default=REPO / "instances" / "v1", help="generated dataset folder")
    parser.add_argument("--published", type=Path, default=None,
                        help="imported published dataset folder: write in/instances_published.json "
                             "and in/instances_published_feedback.json instead")
    parser.add_argument("--describers", type=Path, default=None,
                        help="dataset from `sartco import-instructions`: write in/instances_describers.json instead")
    parser.add_argument("--protocol", choices=("sartco", "paper"), default="sartco",
                        help="paper: write in/instances_paper.json, the paper protocol on the published test files")
    parser.add_argument("--paper-data", type=Path, default=None,
                        help="--protocol paper: the published SARTCo files (default ../shared/sartco-data/published)")
    parser.add_argument("--seed", type=int, default=42, help="seed of the in-context example choice")
    parser.add_argument("--examples", type=int, default=N_EXAMPLES, help="in-context examples (Table 3 cells)")
    parser.add_argument("--ablation-episodes", type=int, default=ABLATION_EPISODES)
    parser.add_argument("--smoke", type=int, default=SMOKE_EPISODES,
                        help=f"episodes per experiment in in/instances_smoke.json (default {SMOKE_EPISODES})")
    parser.add_argument("--attempts", type=int, default=FEEDBACK_ATTEMPTS,
                        help=f"attempts per episode in the feedback experiments (default {FEEDBACK_ATTEMPTS})")
    parser.add_argument("--train", action="store_true",
                        help="write in/instances_train.json (the train split, for training) instead")
    parser.add_argument("--train-episodes", type=int, default=0,
                        help="with --train: episodes per cell (default 0: every train board)")
    parser.add_argument("--fresh", type=int, default=None, metavar="SEED",
                        help="write in/instances_fresh.json: the published test boards beside fresh boards of SEED")
    parser.add_argument("--fresh-episodes", type=int, default=0, help="with --fresh: boards per cell (0: all)")
    args = parser.parse_args(argv)
    if args.attempts < 2:
        print(f"instancegenerator: --attempts must be at least 2, not {args.attempts}", file=sys.stderr)
        return 2
    if args.protocol == "paper":
        return 0 if _write(PaperInstanceGenerator(), "instances_paper.json", seed=args.seed,
                           dataset_dir=args.dataset.resolve(),
                           published_dir=args.paper_data.resolve() if args.paper_data else None) else 2
    if args.smoke < 1:
        print(f"instancegenerator: --smoke must be at least 1, not {args.smoke}", file=sys.stderr)
        return 2
    if args.fresh is not None:
        return 0 if _write(FreshInstanceGenerator(str(GAME_DIR), CELLS), "instances_fresh.json", seed=args.seed,
                           dataset_dir=args.dataset.resolve(), n_examples=args.examples, fresh_seed=args.fresh,
                           published_dir=args.published.resolve() if args.published else None,
                           per_experiment=args.fresh_episodes or None) else 2
    if args.describers is not None:
        outputs = [("instances_describers.json", None, {})]
    elif args.published is not None:
        outputs = [("instances_published.json", None, {}),
                   (f"instances_published{FEEDBACK_SUFFIX}.json", args.attempts, {})]
    elif args.train:
        outputs = [("instances_train.json", None, {"part": "train", "train_episodes": max(args.train_episodes, 0)})]
    else:
        outputs = [("instances.json", None, {}), ("instances_ablations.json", None, {"part": "ablations"}),
                   (f"instances{FEEDBACK_SUFFIX}.json", args.attempts, {}),
                   ("instances_smoke.json", None, {"per_experiment": args.smoke})]
    for name, attempts, part in outputs:
        if not _write(CobotInstructInstanceGenerator(feedback_attempts=attempts), name, seed=args.seed,
                      dataset_dir=args.dataset.resolve(),
                      published_dir=args.published.resolve() if args.published else None,
                      n_examples=args.examples, ablation_episodes=args.ablation_episodes,
                      describers_dir=args.describers.resolve() if args.describers else None, **part):
            return 2
    return 0


def _write(gen: InstanceGenerator, name: str, **kwargs) -> bool:
    """Write one instance file and say what it holds, or say in one line why it could not."""
    try:
        path = gen.generate(name, **kwargs)
    except (UserError, KeyError, ValueError) as exc:
        print(f"instancegenerator: {exc}", file=sys.stderr)
        return False
    exps = gen.instances["experiments"]
    print(f"{path}: {len(exps)} experiments, {sum(len(e['game_instances']) for e in exps)} episodes")
    return True

if __name__ == "__main__":
    sys.exit(main())
