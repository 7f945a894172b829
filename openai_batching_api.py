"""clemcore backend `openai_batching` (looked up as <backend>_api.py in the working directory): an
OpenAI-compatible server used with concurrent requests, `clem run -b 16 -m <model>`.
The implementation lives in the installed package (sartco.clem.batching)."""
from sartco.clem.batching import OpenAIBatchingBackend  # noqa: F401  (clemcore finds the Backend subclass)
