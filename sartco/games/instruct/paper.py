"""The paper protocol in clemcore: cobot_instruct's episodes of the game entry `cobot_instruct_paper`
(instances with `protocol: "paper"`, made from sartco.paper.episodes.build_episodes).

The authors' game sends each turn's message as a user message (the whole history kept) and never
aborts: their scorer reads every answer after the dialogue (sartco.paper.reading.read_answer)
and scores each turn (sartco.paper.scoring.score_dialogue: EM, CB pass, ES with the "while"
refusal). `finish_paper` does the same once the last answer is in, logs one GM->GM `paper_turn`
event per turn (the reading and its scores; shown escaped, the code as code blocks) and the dialogue's scores under PAPER_KEY, and also
records our own build of the whole answer (sartco.clem.core.parsing on each answer, the turns joined, run
once on a fresh board: ES, cell F1, error category; an answer without code is our parse_error,
but the episode goes on). The episode succeeds when every turn's ES does.

The scores of a paper episode are those of the game's scorer (scorer.InstructScorer).
"""
from __future__ import annotations

from sartco.clem.core.instance_checks import json_fields
from sartco.clem.core.building import build_answers, record_build
from sartco.clem.core.errors import HarnessFault
from sartco.clem.core.transcript import code_block, text_block
from sartco.episode import PAPER_KEY, PAPER_SCORES, PaperExperiment, PaperProtocolEpisode
from sartco.paper import PROTOCOL
from sartco.paper.table3 import generation, load_table3
from sartco.world import DEFAULT_COLS, DEFAULT_ROWS, ErrorCode

PAPER_EVENT = "paper_turn"     # one GM->GM event per turn: what the authors' scorer read and scored
# what cobot_instruct's master and scorer read from a paper episode (checked before clem run plays)
PAPER_EPISODE_FIELDS = json_fields(PaperProtocolEpisode)


def is_paper(fields: dict) -> bool:
    """True for an instance (or experiment) of the paper protocol."""
    return fields.get("protocol") == PROTOCOL


def gold_code(episode: dict) -> str:
    """Our gold code of a paper episode, for our EM and CodeBLEU: the turns' puts joined
    (multi-turn), function + usage (functions), the repetition code (repetition)."""
    first = episode["gold"][0]
    if "function" in first:
        return first["function"]  # the paper's gold function key is function + "\n" + usage
    return "\n".join(turn["output"] for turn in episode["gold"])


def experiment_fields(episode: dict) -> PaperExperiment:
    """What an experiment of one Table 3 cell records (the generator adds its name): the protocol,
    the cell, where its examples came from, and the generation settings the paper used."""
    cell = episode["cell"]
    return PaperExperiment(protocol=PROTOCOL, board_type=cell["board"], object_type=cell["object"], task=cell["task"],
                           source=cell["source"], instructions=cell["instructions"], variant=episode["variant"],
                           file=episode["file"], split="test", ablation=None, examples_from=episode["examples_from"],
                           generation=generation(load_table3()))


def instance_fields(episode: dict) -> PaperProtocolEpisode:
    """A game instance of a paper episode (PaperEpisode.to_json()): the episode as it is, plus the
    board fields our own build and scores read (sartco.clem.core.answer_builds.build_for, BuildScorer)."""
    cell = episode["cell"]
    return {**episode, "board_id": episode["id"], "board_type": cell["board"], "object_type": cell["object"],
            "task": cell["task"], "rows": DEFAULT_ROWS, "cols": DEFAULT_COLS,
            "given_code": episode["given_function"], "gold_code": gold_code(episode)}


def shown(verdict: str, reading: dict[str, str]) -> str:
    """A paper_turn event as the transcript shows it (display form, HTML-escaped): the verdict,
    then each value the authors' scorer read as a code block that keeps its line breaks."""
    parts = [text_block(verdict)]
    for key, text in reading.items():
        parts += [text_block(f"{key}:"), code_block(text) if text.strip() else text_block("(nothing)")]
    return "\n\n".join(parts)


def finish_paper(game_master, instance: dict, answers: list[str]) -> None:
    """The dialogue is over: score it as the authors did, record ours beside it, set the outcome."""
    from sartco.paper.reading import read_answer
    from sartco.paper.scoring import score_dialogue

    score = score_dialogue(answers, instance)
    check_turns(score)
    turns = []
    for k, (answer, turn) in enumerate(zip(answers, score.turns)):
        reading = read_answer(answer, instance["variant"])
        entry = {"turn": k, "reading": reading, **turn.to_json()}
        turns.append(entry)
        verdict = " ".join(f"{name.split()[1]} {int(entry[key])}" for key, name in PAPER_SCORES.items())
        why = f" ({turn.category}: {turn.message})" if turn.category else ""
        game_master.log_event("GM", "GM", {"type": PAPER_EVENT, "turn": k, "scores": entry,
                                           "content": shown(f"paper protocol, turn {k + 1}: {verdict}{why}", reading)})
    alone = score if not instance["given_function"] else score_dialogue(answers, instance, alone=True)
    check_turns(alone)
    game_master.log_key(PAPER_KEY, {"em": score.em, "cb": score.cb, "es": score.es, "es_leak_free": alone.es,
                                    "turns": turns})
    record = build_answers(instance, answers)
    record_build(game_master, [record], final=True, instance=instance, share=score.es)


def check_turns(score) -> None:
    """HarnessFault when the sandbox failed on a turn (harness_error): never a turn the model lost."""
    for turn in score.turns:
        if turn.category == ErrorCode.HARNESS_ERROR:
            raise HarnessFault(f"sandbox: {turn.message}")
