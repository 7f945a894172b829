# written by `sartco register`: clemcore loads this file by its path; the backend is in the sartco package
"""clemcore backend `openai_batching`: an OpenAI-compatible server used with concurrent requests,
`clem run -b 16 -m <model>`. `sartco register DIR` copies this file to DIR/openai_batching_api.py
(sartco.register), where clemcore finds it; the implementation lives in sartco.clem.tooling.batching."""
from sartco.clem.tooling.batching import OpenAIBatchingBackend  # noqa: F401
