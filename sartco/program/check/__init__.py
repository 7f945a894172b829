"""The check that reads a program before it runs: the allowed subset as data (allowed.py), each
node type's check and instrumentation (nodes.py), and `prepare(source)`, one linear pass
(instrument.py; with `heads`, programs that differ only in their last line share the rest's).
Pure: no process, no state. The module map: docs/sandbox.md, "The sandbox's rooms".
"""
