"""Code-text metrics of the paper: exact match and CodeBLEU, both against the gold code of the same style.

exact_match
    1 when the two programs are the same text after normalising only what carries no meaning and
    what language models vary at random: line endings (CRLF/CR -> LF), trailing whitespace on a
    line, blank lines, and whitespace before the first and after the last line. Indentation,
    spacing inside a line, quote style and comments are kept: the paper's EM compares code text,
    and `'red'` vs `"red"` or `x=1` vs `x = 1` is a different text (CodeBLEU and execution
    success are the metrics that forgive it).

code_bleu
    The `codebleu` package (0.7.0, tree-sitter-python 0.21), lang python, weights 0.25 x 4, one
    prediction against one reference, exactly as `codebleu.calc_codebleu([gold], [pred], "python")`
    computes it, with three differences, all documented and tested:
    1. Deterministic. codebleu's data-flow match builds the parent-variable lists of its data-flow
       graph with `list(set(...))` of variable names, so the variable numbering, and with it the
       score, depends on the process's string hash seed (PYTHONHASHSEED): on 600 random pairs of
       published gold programs, 116 scores differed between hash seeds, by up to 0.057
       (k4black/codebleu issue #35, microsoft/CodeXGLUE issue #152). We sort those lists before
       codebleu normalises them. With any fixed order codebleu itself gives the same number
       (tests/scores check this against `calc_codebleu` with the same ordering), so the score is
       one that the package computes, just always the same one.
    2. An empty (or all-whitespace) prediction scores 0.0; codebleu gives it 0.25 (its
       `theta * (dataflow or 1)` counts a data-flow score of 0 as 1; k4black/codebleu issue #59).
       Any other prediction keeps that quirk: a non-empty but unrelated answer can score 0.25.
    3. A pathological answer whose syntax tree is too big for codebleu's quadratic sub-tree
       listing (MAX_SEXP_WORK, 300x the longest published gold program) scores 0.0 with a reason
       instead of taking seconds to minutes and gigabytes.
    An exception inside codebleu gives 0.0 with the reason in `CodeBleu.reason`, never a crash.

Cost: `python -m sartco.scores.bench_codebleu DATASET_DIR` times it on the gold programs of a dataset.
The parsers are not the cost (a tree-sitter Parser is built in about 0.3 us; the Language object
and the keyword list are built once here); the time goes into codebleu's own Python: removing
comments with `tokenize`, the data-flow graph and the sub-tree lists, each done for both programs
on every call. Those are pure functions of one program's text, so we compute them once per text
(a gold program is analysed once however many answers are scored against it) and look sub-trees
up in a set instead of a list; the numbers are bit-for-bit those of codebleu (tested). Whole
results are memoised per (prediction, gold) pair as well.
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path
from types import SimpleNamespace

WEIGHTS = (0.25, 0.25, 0.25, 0.25)
LANG = "python"
_BLANKS = re.compile(r"[ \t\f\v]+$", re.MULTILINE)


def normalize_code(code: str) -> str:
    """The text exact match compares: LF line ends, no trailing spaces, no blank lines."""
    text = code.replace("\r\n", "\n").replace("\r", "\n")
    text = _BLANKS.sub("", text)
    return "\n".join(line for line in text.split("\n") if line.strip())


def exact_match(pred: str, gold: str) -> int:
    """1 if pred is gold up to line endings, trailing whitespace and blank lines, else 0."""
    return int(normalize_code(pred or "") == normalize_code(gold or ""))


@dataclass(frozen=True, slots=True)
class CodeBleu:
    """CodeBLEU and its four components; reason says why the score is 0.0 by rule, else ""."""

    score: float
    ngram: float = 0.0
    weighted_ngram: float = 0.0
    syntax: float = 0.0
    dataflow: float = 0.0
    reason: str = ""


def code_bleu(pred: str, gold: str) -> float:
    """CodeBLEU of pred against gold (weights 0.25 each, python); 0.0 for an empty prediction."""
    return code_bleu_detail(pred, gold).score


def code_bleu_detail(pred: str, gold: str) -> CodeBleu:
    if not isinstance(pred, str) or not pred.strip():
        return CodeBleu(0.0, reason="empty prediction")
    if not isinstance(gold, str) or not gold.strip():
        return CodeBleu(0.0, reason="empty gold code")
    return _code_bleu(pred, gold)


def analyse_gold(gold: str) -> None:
    """Analyse a gold program before its answers are scored (the per-program half of code_bleu,
    memoised): done ahead of an episode's step (sartco.clem.core.ahead), the step finds it."""
    if isinstance(gold, str) and gold.strip():
        try:
            _analyse(gold.strip())
        except Exception:  # code_bleu meets it again when it scores, and says why
            pass


@lru_cache(maxsize=4096)
def _code_bleu(pred: str, gold: str) -> CodeBleu:
    try:
        return _compute(pred, gold)
    except TooLarge as exc:
        return CodeBleu(0.0, reason=str(exc))
    except Exception as exc:  # a scorer must not crash on a strange answer
        return CodeBleu(0.0, reason=f"codebleu failed: {type(exc).__name__}: {exc}"[:300])


@lru_cache(maxsize=1)
def _resources() -> SimpleNamespace:
    """codebleu's modules, the python Language and keyword list: built once per process."""
    from codebleu import bleu, dataflow_match, weighted_ngram_match
    from codebleu.codebleu import PACKAGE_DIR
    from codebleu.parser import DFG_python, remove_comments_and_docstrings
    from codebleu.utils import get_tree_sitter_language

    language = get_tree_sitter_language(LANG)
    keywords = frozenset(
        line.strip() for line in (Path(PACKAGE_DIR) / "keywords" / f"{LANG}.txt").read_text(encoding="utf-8").splitlines()
    )
    return SimpleNamespace(bleu=bleu, weighted_ngram_match=weighted_ngram_match, dataflow_match=dataflow_match,
                           dfg_python=DFG_python, strip_comments=remove_comments_and_docstrings,
                           language=language, keywords=keywords)


def _compute(pred: str, gold: str) -> CodeBleu:
    """calc_codebleu for one pair, step by step as in codebleu/codebleu.py 0.7.0."""
    cb = _resources()
    reference = gold.strip()
    hypothesis = pred.strip()

    ref_tokens = reference.split()
    hyp_tokens = hypothesis.split()
    ngram = cb.bleu.corpus_bleu([[ref_tokens]], [hyp_tokens])
    weights = {token: 1 if token in cb.keywords else 0.2 for token in ref_tokens}
    weighted = cb.weighted_ngram_match.corpus_bleu([[[ref_tokens, weights]]], [hyp_tokens])

    ref, cand = _analyse(reference), _analyse(hypothesis)
    # syntax match (codebleu syntax_match.corpus_syntax_match): reference sub-trees found among the
    # candidate's, over all reference sub-trees
    syntax = sum(1 for sexp in ref.sexps if sexp in cand.sexp_set) / len(ref.sexps)
    # data-flow match (codebleu dataflow_match.corpus_dataflow_match), each candidate flow used once
    if ref.dataflow:
        remaining = list(cand.dataflow)
        matched = 0
        for item in ref.dataflow:
            if item in remaining:
                matched += 1
                remaining.remove(item)
        dataflow = matched / len(ref.dataflow)
    else:
        dataflow = 0.0  # codebleu logs a warning and returns 0 here; the `or 1` below then applies

    alpha, beta, gamma, theta = WEIGHTS
    score = alpha * ngram + beta * weighted + gamma * syntax + theta * (dataflow or 1)
    return CodeBleu(float(score), float(ngram), float(weighted), float(syntax), float(dataflow))


class TooLarge(ValueError):
    """A program whose sub-tree list would be too big to build (see MAX_SEXP_WORK)."""


# codebleu lists every sub-tree as its S-expression text, so its work and memory grow with the
# sum over nodes of their depth: quadratic in a deeply nested answer ("x = 1+1+...": 2,000 terms
# take 2.3 s, 30,000 would need gigabytes). The longest published gold program sums to 3,202;
# above this budget a program is not scored (0.0 with a reason) instead of stalling the scorer.
MAX_SEXP_WORK = 1_000_000


def _check_size(root) -> None:
    work, stack = 0, [(root, 1)]
    while stack:
        node, depth = stack.pop()
        work += depth
        if work > MAX_SEXP_WORK:
            raise TooLarge(f"program too large or deeply nested for CodeBLEU (over {MAX_SEXP_WORK:,} node-depth units)")
        stack.extend((child, depth + 1) for child in node.children)


@dataclass(frozen=True, slots=True)
class _Analysis:
    sexps: tuple[str, ...]       # every sub-tree with children, as codebleu lists them
    sexp_set: frozenset[str]
    dataflow: tuple              # normalised data-flow items (var, relation, [parent vars])


@lru_cache(maxsize=1024)  # an analysis holds up to ~30 kB of sub-tree text (the longest published gold)
def _analyse(code: str) -> _Analysis:
    """The per-program half of syntax and data-flow match: a pure function of the text, so
    memoised (a gold program is analysed once, however many answers are scored against it)."""
    cb = _resources()
    from tree_sitter import Parser

    try:
        code = cb.strip_comments(code, LANG)
    except Exception:  # as codebleu does
        pass
    parser = Parser()
    parser.language = cb.language
    root = parser.parse(bytes(code, "utf8")).root_node
    _check_size(root)
    sexps, stack = [], [root]
    while stack:  # codebleu's get_all_sub_trees, same order
        node = stack.pop()
        sexps.append(str(node))
        stack.extend(child for child in node.children if child.children)
    graph = cb.dataflow_match.get_data_flow(code, [parser, cb.dfg_python])
    ordered = [(d[0], d[1], d[2], sorted(d[3]), d[4]) for d in graph]  # the one change: sorted
    return _Analysis(tuple(sexps), frozenset(sexps), tuple(cb.dataflow_match.normalize_dataflow(ordered)))
