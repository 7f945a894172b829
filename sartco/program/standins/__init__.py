"""What a program calls while it runs: the budgets, the checked builtins, conversions, formatting and
methods, the stand-in modules, and the rules of a program's classes and attributes.

Imported by the check (which names what they offer) and by the child (which runs programs with
them); imports nothing else of the sandbox. The module map: docs/sandbox.md, "The sandbox's rooms".
"""
