"""The authors' reading of one answer (paper-protocol README, "Reading an answer").

    read_answer(answer: str, variant: str) -> dict[str, str]
        multi_turn, regular*:  {"output": ...}
        single_turn*:          {"function": ..., "usage": ...}

For each expected label (Output; or Function and Usage) the value is the text after the first
occurrence of the label, stripped; a missing label gives the whole answer stripped (output,
function) or "" (usage). An answer is never refused. Clean-up, in this order: every "```python",
then every "```" removed, strip; function: if it contains "Usage", remove "Usage:" (or else
"Usage"), strip, drop a first line that is exactly ":"; but if the function text before that step
contains "Function", the result is that earlier text with every "Function" removed instead;
usage: every "Usage" removed, strip; output: a leading ":" dropped, strip.

"After the first occurrence" is `answer.split(label, 1)[1]`: the README's rules on a function
text containing "Function" and on removing every "Usage" from a usage text can only apply when
the rest of the answer is kept past a second occurrence of the label.
"""
from __future__ import annotations

from .vocabulary import LABELS, VARIANTS


def after_label(answer: str, label: str, missing: str) -> str:
    """The text after the first occurrence of label, stripped; `missing` when there is none."""
    if label not in answer:
        return missing
    return answer.split(label, 1)[1].strip()


def unfence(text: str) -> str:
    return text.replace("```python", "").replace("```", "").strip()


def clean_function(text: str) -> str:
    before = text
    if "Usage" in text:
        text = text.replace("Usage:", "") if "Usage:" in text else text.replace("Usage", "")
        text = text.strip()
        first, _, rest = text.partition("\n")
        if first == ":":
            text = rest
    if "Function" in before:
        text = before.replace("Function", "")
    return text


def read_answer(answer: str, variant: str) -> dict[str, str]:
    """The values the authors' scorer reads from one answer of a turn (see the module doc)."""
    if variant not in VARIANTS:
        raise ValueError(f"unknown variant {variant!r}; expected one of {', '.join(VARIANTS)}")
    answer = answer if isinstance(answer, str) else ""
    family = VARIANTS[variant].family
    whole = answer.strip()
    if family == "single_turn":
        function_label, usage_label = LABELS[family]
        function = clean_function(unfence(after_label(answer, function_label, whole)))
        usage = unfence(after_label(answer, usage_label, "")).replace(usage_label, "").strip()
        return {"function": function, "usage": usage}
    output = unfence(after_label(answer, LABELS[family][0], whole))
    if output.startswith(":"):
        output = output[1:].strip()
    return {"output": output}
