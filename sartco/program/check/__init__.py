"""The check that reads a program before it runs: the allowed subset as data (allowed.py), each
node type's check and instrumentation (nodes.py), and `prepare(source)`, one linear pass
(instrument.py). Pure: no process, no state. The module map: docs/sandbox.md, "The sandbox's rooms".
"""
