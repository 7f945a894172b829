"""Backends and bench tooling: the batching backend, the rule-based backend, the stub server,
bench-run, sample, resume and the completeness check (see sartco.clem)."""
