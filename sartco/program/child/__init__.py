"""The child's side of the wall: the template process (template.py) that forks one confined child
per program, the kernel's walls it raises (confine.py), the run of one program (runtime.py, with
namespaces.py for the paper protocol), and the answer a child sends (result.py). Nothing here
decides a board: the parent does (verdict.py). The module map: docs/sandbox.md, "The sandbox's rooms".
"""
