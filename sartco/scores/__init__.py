"""Scores: exact match and CodeBLEU (the per-episode record is sartco.clem.core.building.BuildRecord, turned into numbers by sartco.clem.core.scoring.BuildScorer; tables by sartco.report)."""
from .metrics import CodeBleu, code_bleu, code_bleu_detail, exact_match, normalize_code

__all__ = ["CodeBleu", "code_bleu", "code_bleu_detail", "exact_match", "normalize_code"]
