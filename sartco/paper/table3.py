"""The paper's Table 3 as data: `table3.json` in ../shared/sartco-data/paper-protocol, read at run
time (the figures of CodeLlama-34B, GPT-4 and Claude-3 per cell, and the generation settings the
paper used). One line naming the file for a file that is missing or not the table.
"""
from __future__ import annotations

import json
from pathlib import Path

from sartco.dataset import SHARED_DATA
from sartco.errors import UserError
from sartco.published.files import require_data

TABLE3 = SHARED_DATA / "paper-protocol" / "table3.json"
CELL_KEYS = ("instructions", "board", "object", "task", "variant")
MODEL_WRITTEN = "codellama"  # the source of the paper's model-written rows


def load_table3(path: Path = TABLE3) -> dict:
    require_data(path)
    try:
        table = json.loads(Path(path).read_text(encoding="utf-8"))
        generation(table)
        for cell in table["cells"]:
            cell_key({**cell, "source": cell_source(cell)}), dict(cell["scores"])
    except (OSError, ValueError) as exc:
        raise UserError(f"{path}: cannot read the paper's Table 3 ({exc})") from None
    except (KeyError, TypeError) as exc:
        raise UserError(f"{path}: not the paper's Table 3 (missing {exc})") from None
    return table


def generation(table: dict) -> dict:
    """The paper's generation settings in clemcore's gen_args names."""
    s = table["settings"]
    return {"temperature": float(s["temperature"]), "max_tokens": int(s["max_new_tokens"])}


def cell_source(cell: dict) -> str:
    """The instruction source of a Table 3 cell (its model-written rows: the CodeLlama-written files)."""
    return cell["instructions"] if cell["instructions"] != "model" else MODEL_WRITTEN


def cell_key(fields: dict) -> tuple:
    return tuple(fields[k] for k in CELL_KEYS) + (fields["source"],)
