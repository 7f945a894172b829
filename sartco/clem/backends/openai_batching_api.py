"""clemcore backend `openai_batching`: an OpenAI-compatible server used with concurrent requests,
`clem run -b 16 -m <model>`. A packaged backend file (sartco.clem.packaged): clemcore finds it
wherever sartco is installed; the implementation lives in sartco.clem.tooling.batching."""
from sartco.clem.tooling.batching import OpenAIBatchingBackend  # noqa: F401
