"""Scores: exact match, CodeBLEU, the per-episode score record (and the report tables)."""
from .episode import EpisodeScore
from .metrics import CodeBleu, code_bleu, code_bleu_detail, exact_match, normalize_code

__all__ = ["CodeBleu", "EpisodeScore", "code_bleu", "code_bleu_detail", "exact_match", "normalize_code"]
