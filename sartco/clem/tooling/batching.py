"""clemcore backend `openai_batching`: an OpenAI-compatible server (vLLM, llama.cpp server with
parallel slots, an API with rate limit to spare) used concurrently.

clemcore 3.7 batches only models that are a `BatchGenerativeModel`; its `openai_compatible`
backend is not one, so `clem run` sends one request and waits. This backend is: `clem run -b N
-m <model>` hands it N requests at a time (one per running episode) and it sends them
concurrently, at most `concurrency` in flight. Each request is exactly the one clemcore's
openai_compatible backend sends (its OpenAIModel builds it: model id, messages, temperature,
max_tokens, the registry entry's `extra_body`), so a deterministic server gives the same answers
and scores as the sequential run. Retries: 429, 5xx, connection errors and timeouts are retried
with exponential backoff (`backoff` x 2^k seconds, or the server's Retry-After), up to `retries`
times and within `retry_budget` seconds in all (tries and waits of one request); any other
error, or the last retry's, ends the request with that error, logged. Every try waits at most
`timeout` seconds for its answer (default 120), so a hung server costs at most about
retry_budget + timeout seconds per request, never the client's default (600 s per try). In a
sequential run (no -b) clemcore logs the error and goes on with the next episode (the episode has
no interactions.json); in a batched run (-b N) the error ends `clem run`.
`cache`: a folder for the opt-in response cache (sartco.clem.tooling.response_cache; temperature 0 only).
`-b 1` (or no -b) plays sequentially through the same code path.

Registry entry (model_registry.json; key.json's `openai_compatible` entry gives base_url, api_key):
  {"model_name": "my-model", "model_id": "<id the server knows>", "backend": "openai_batching",
   "model_config": {"concurrency": 16, "retries": 5, "backoff": 1.0, "timeout": 120, "retry_budget": 600,
                    "cache": "cache/my-model"}}
clemcore finds the backend where `sartco register DIR` wrote DIR/openai_batching_api.py (a copy of
sartco/clem/backends/openai_batching_api.py; sartco.register).
"""
from __future__ import annotations

import inspect
import logging
import time
from concurrent.futures import ThreadPoolExecutor
from typing import Any

import httpx
import openai
from clemcore.backends import BatchGenerativeModel, ModelSpec
from clemcore.backends.openai_api import OpenAI, OpenAIModel
from clemcore.backends.utils import augment_response_object, ensure_messages_format

from sartco.clem.core.outcomes import NO_ANSWER, NoAnswer
from sartco.settings import MODEL_SERVER

from .response_cache import ResponseCache

log = logging.getLogger(__name__)

KEY_NAME = "openai_compatible"   # the same key.json entry as clemcore's openai_compatible backend
DEFAULTS = {**MODEL_SERVER, "cache": None}   # a model entry's model_config overrides these (sartco.settings)
MAX_DELAY = 60.0                 # seconds, the longest wait between two tries
RETRIED = (openai.RateLimitError, openai.InternalServerError, openai.APIConnectionError)  # 429, 5xx, network, timeout

# one request exactly as clemcore's OpenAIModel makes it: its method body under the same two
# decorators (message checks; the response object's clem_player metadata), without its blanket
# retry (3 tries, 10 s apart, on any error): the retry policy here is our own, below
_request_once = augment_response_object(ensure_messages_format(inspect.unwrap(OpenAIModel.generate_response)))


class BatchingOpenAIModel(OpenAIModel, BatchGenerativeModel):

    def __init__(self, client: openai.OpenAI, model_spec: ModelSpec):
        super().__init__(client, model_spec)
        config = {**DEFAULTS, **(getattr(model_spec, "model_config", None) or {})}
        self.concurrency = int(config["concurrency"])
        self.retries = int(config["retries"])
        self.backoff = float(config["backoff"])
        self.timeout, self.retry_budget = float(config["timeout"]), float(config["retry_budget"])
        if self.concurrency < 1 or self.retries < 0 or self.backoff < 0 or self.timeout <= 0 or self.retry_budget < 0:
            raise ValueError(f"model_config of {model_spec.model_name}: concurrency >= 1, retries >= 0, backoff >= 0, "
                             f"timeout > 0 and retry_budget >= 0 expected, got {self.concurrency}, {self.retries}, "
                             f"{self.backoff}, {self.timeout}, {self.retry_budget}")
        self.client = client.with_options(timeout=self.timeout)  # seconds per try (connect, read, write)
        self.cache = ResponseCache(config["cache"]) if config["cache"] else None
        self._pool: ThreadPoolExecutor | None = None

    def generate_response(self, messages: list[dict]) -> tuple[Any, Any, str]:
        return self._answer(messages)

    def generate_batch_response(self, batch_messages: list[list[dict]]) -> list[tuple[Any, Any, str]]:
        """The batch's requests concurrently (at most `concurrency` in flight), answers in order."""
        if self._pool is None:
            self._pool = ThreadPoolExecutor(self.concurrency, thread_name_prefix="openai_batching")
        return list(self._pool.map(self._answer, batch_messages))

    def _answer(self, messages: list[dict]) -> tuple[Any, Any, str]:
        """From the cache when it holds the answer (temperature 0 only), else from the server."""
        if self.cache is None or self.gen_args.get("temperature"):
            return self._with_retries(messages)
        settings = {**self.gen_args, "extra_body": (getattr(self.model_spec, "model_config", None) or {}).get("extra_body")}
        key = self.cache.key(self.model_spec.model_id, messages, settings)
        found = self.cache.get(key)
        if found is None:
            found = self._with_retries(messages)
            if not isinstance(found[2], NoAnswer):  # a failure is never cached
                self.cache.put(key, found)
        return found

    def _with_retries(self, messages: list[dict]) -> tuple[Any, Any, str]:
        start = time.monotonic()
        for attempt in range(self.retries + 1):
            try:
                return _request_once(self, messages)
            except openai.APIError as error:
                delay = retry_delay(error, attempt, self.backoff)
                spent = time.monotonic() - start
                if not isinstance(error, RETRIED) or attempt == self.retries or spent + delay > self.retry_budget:
                    return self._no_answer(messages, error, attempt + 1, spent)
                log.warning("%s: %s; retry %d of %d in %.1f s", self.name, type(error).__name__,
                            attempt + 1, self.retries, delay)
                time.sleep(delay)
        raise AssertionError("unreachable")

    def _no_answer(self, messages: list[dict], error: openai.APIError, tries: int, spent: float) -> tuple[Any, Any, str]:
        """The request given up: logged, and answered by a NoAnswer that carries the reason (the
        game master records the episode as harness_error; the model is not charged)."""
        log.error("%s: %s after %d tries in %.1f s (timeout %.0f s, retries %d, retry budget %.0f s): "
                  "request aborted", self.name, type(error).__name__, tries, spent, self.timeout,
                  self.retries, self.retry_budget)
        what = "no answer" if isinstance(error, openai.APITimeoutError) else f"{type(error).__name__} ({error})"
        answer = NoAnswer(f"{NO_ANSWER}{what} after {tries} {'try' if tries == 1 else 'tries'} in {spent:.0f} s "
                          f"(timeout {self.timeout:g} s)")
        return messages, {"error": answer.reason, "clem_player": {"response": "", "model_name": self.name}}, answer


def retry_delay(error: Exception, attempt: int, backoff: float) -> float:
    """The server's Retry-After (seconds) when it sent one, else backoff x 2^attempt; at most MAX_DELAY."""
    response = getattr(error, "response", None)
    after = response.headers.get("retry-after") if response is not None else None
    try:
        delay = float(after) if after is not None else backoff * 2 ** attempt
    except ValueError:  # an HTTP date: not worth parsing, use the backoff
        delay = backoff * 2 ** attempt
    return max(0.0, min(delay, MAX_DELAY))


class OpenAIBatchingBackend(OpenAI):
    def __init__(self):
        super().__init__(key_name=KEY_NAME)

    def _make_api_client(self):
        # retries are ours (above), so the client makes none; the connection pool holds the
        # concurrent requests (clemcore's openai_compatible also turns certificate checks off)
        return openai.OpenAI(base_url=self.key["base_url"], api_key=self.key["api_key"], max_retries=0,
                             http_client=httpx.Client(verify=False, limits=httpx.Limits(max_connections=256)))

    def get_model_for(self, model_spec: ModelSpec) -> BatchingOpenAIModel:
        return BatchingOpenAIModel(self.client, model_spec)
