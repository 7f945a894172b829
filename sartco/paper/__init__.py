"""The paper protocol: how the SARTCo paper's Table 3 was measured, as a library.

The data it follows is ../shared/sartco-data/paper-protocol (README.md: the rules; *.template:
the authors' builder prompts; table3.json: the paper's figures); it is read at run time, never
copied. Our own protocol (the project's prompts, whole-program metrics, cell F1, error taxonomy)
is named "sartco" and lives in sartco.instances / sartco.clem; both run the same world, sandbox
and boards and differ only in prompt, answer reading and scoring.

    from sartco.paper import PROTOCOL                  # "paper" (ours: OUR_PROTOCOL = "sartco")
    from sartco.paper.episodes import PaperEpisode, build_episodes, DEFAULT_PUBLISHED
    from sartco.paper.reading import read_answer       # read_answer(answer, variant) -> {key: text}
    from sartco.paper.scoring import TurnScore, DialogueScore, score_turn, score_dialogue

Modules:
  vocabulary.py  file stems, variants (dialogue keys) and their Table 3 cell fields, labels, templates
  episodes.py    every Table 3 cell on the published test files: prompts, examples, gold, mock answers
  reading.py     the authors' reading of an answer (labels, fences, clean-up)
  scoring.py     per-turn EM / CB pass / ES (the sandbox only) and per-dialogue shares
The commands `sartco export-prompts` and `sartco score-responses` (sartco.protocols) speak
JSON lines over both protocols.
"""
from .vocabulary import OUR_PROTOCOL, PROTOCOL

__all__ = ["PROTOCOL", "OUR_PROTOCOL"]
