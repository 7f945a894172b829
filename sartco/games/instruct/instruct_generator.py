"""The base of cobot_instruct's instance generators (sartco.games.instruct.instancegenerator and
sartco.games.instruct.fresh): one experiment per cell, with or without execution feedback, named by
sartco.dataset.experiment_name, and its episodes from board records, each with its in-context
examples, game_id counted from 0 in each experiment."""
from __future__ import annotations

from sartco.clem.core.instance_values import InstanceGenerator
from sartco.dataset import BoardKind, experiment_name
from sartco.episode import InstructExperiment
from sartco.instances.examples import select_examples
from sartco.instances.prompts import SECTIONS

from .episodes import instruct_episode

FEEDBACK = "feedback"           # the variant of the feedback experiments: <cell>_<task>_<source>_feedback
FEEDBACK_SUFFIX = f"_{FEEDBACK}"  # and of their files: instances_feedback.json


class InstructGenerator(InstanceGenerator):

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
