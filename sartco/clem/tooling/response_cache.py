"""The opt-in response cache of the `openai_batching` backend (sartco.clem.tooling.batching): answers on
disk, keyed by model id, messages and generation settings, so that a repeated run at
temperature 0 costs no model call.

Turned on by `"cache": "<folder>"` in the model entry's model_config (relative to the working
directory of `clem run`). One JSON file per request, <folder>/<key[:2]>/<key>.json, holding what
the request returned (prompt, response object, text); the key is the sha256 of the model id, the
messages and the generation settings (temperature, max_tokens, the entry's extra_body) as
canonical JSON. Only answers at temperature 0 are stored and served: at temperature > 0 every
request reaches the server, so samples (`sartco sample`) stay samples. Answers are written
atomically (a temporary file, then a rename), so concurrent requests and an interrupted run
leave no half-written entry. `hits` and `misses` count this process's look-ups.
"""
from __future__ import annotations

import hashlib
import json
import os
import threading
from pathlib import Path
from typing import Any


class ResponseCache:
    def __init__(self, folder: str | Path):
        self.folder = Path(folder)
        self.hits = self.misses = 0
        self._lock = threading.Lock()

    @staticmethod
    def key(model_id: str, messages: list[dict], settings: dict) -> str:
        text = json.dumps({"model": model_id, "messages": messages, "settings": settings},
                          sort_keys=True, ensure_ascii=True, default=str)
        return hashlib.sha256(text.encode("ascii")).hexdigest()

    def _path(self, key: str) -> Path:
        return self.folder / key[:2] / f"{key}.json"

    def get(self, key: str) -> tuple[Any, Any, str] | None:
        path = self._path(key)
        try:
            entry = json.loads(path.read_text(encoding="utf-8"))
            found = (entry["prompt"], entry["response"], entry["text"])
        except (OSError, ValueError, KeyError, TypeError):
            found = None   # absent, or unreadable: asked again and overwritten
        with self._lock:
            if found is None:
                self.misses += 1
            else:
                self.hits += 1
        return found

    def put(self, key: str, result: tuple[Any, Any, str]) -> None:
        prompt, response, text = result
        path = self._path(key)
        path.parent.mkdir(parents=True, exist_ok=True)
        temporary = path.with_suffix(f".{os.getpid()}.{threading.get_ident()}.tmp")
        temporary.write_text(json.dumps({"prompt": prompt, "response": response, "text": text}, ensure_ascii=True),
                             encoding="utf-8")
        os.replace(temporary, path)
