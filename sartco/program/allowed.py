"""The subset of Python a program may use, as data: the builtins, the attribute names, the
syntax node types (with the fields that hold their children) and why the others are refused.

Allowed: every statement and expression of Python except with, async/await, match and
try/except* (see WHAT for why); class statements as classes.py builds them; imports of the
stand-in modules of modules.py only; any name except those starting with two underscores (but
`__name__` may be read: `if __name__ == "__main__":`), `put`/`init_board` never rebound, and a
builtin outside ALLOWED_BUILTINS only if the program binds that name itself (`type = 'nut'`);
attributes as attributes.py rules (ATTRIBUTES: the names the sandbox offers).
"""
from __future__ import annotations

import ast
import builtins

from .attributes import OFFERED, RECORD_NAMES, TYPES
from .classes import EXCEPTIONS
from .methods import METHODS
from .modules import MEMBERS

ALLOWED_BUILTINS = frozenset(
    "range zip enumerate len min max abs sum sorted reversed any all round divmod "
    "int str bool list tuple dict set frozenset float print isinstance issubclass map filter next iter "
    "chr ord pow format repr ascii hex bin oct callable hash slice super property staticmethod classmethod".split()
) | EXCEPTIONS
PROVIDED = frozenset({"put", "init_board"})  # `board` is provided too, but may be rebound
DENIED = frozenset(dir(builtins)) - ALLOWED_BUILTINS - {"True", "False", "None", "Ellipsis", "NotImplemented", "__name__"}
# every attribute name the sandbox offers (a program may also read the names it defines)
ATTRIBUTES = METHODS.union(*MEMBERS.values(), *TYPES.values(), RECORD_NAMES, OFFERED)


# the fields of each allowed node type that hold child nodes; a type not listed is forbidden
A = ast
FIELDS: dict[type, tuple[str, ...]] = {
    A.Module: ("body",), A.ClassDef: ("decorator_list", "bases", "body"), A.FunctionDef: ("decorator_list", "args", "body", "returns"), A.Return: ("value",),
    A.Assign: ("targets", "value"), A.AugAssign: ("target", "value"),
    A.AnnAssign: ("target", "annotation", "value"), A.Delete: ("targets",),
    A.For: ("target", "iter", "body", "orelse"), A.While: ("test", "body", "orelse"),
    A.If: ("test", "body", "orelse"), A.Expr: ("value",), A.Pass: (), A.Break: (), A.Continue: (),
    A.Try: ("body", "handlers", "orelse", "finalbody"), A.ExceptHandler: ("type", "body"),
    A.Raise: ("exc", "cause"), A.Assert: ("test", "msg"), A.Global: (), A.Nonlocal: (),
    A.Import: (), A.ImportFrom: (),
    A.BoolOp: ("values",), A.NamedExpr: ("target", "value"), A.BinOp: ("left", "right"),
    A.UnaryOp: ("operand",), A.Lambda: ("args", "body"), A.IfExp: ("test", "body", "orelse"),
    A.Dict: ("keys", "values"), A.Set: ("elts",), A.ListComp: ("elt", "generators"),
    A.SetComp: ("elt", "generators"), A.GeneratorExp: ("elt", "generators"),
    A.DictComp: ("key", "value", "generators"), A.Compare: ("left", "comparators"),
    A.Call: ("func", "args", "keywords"), A.FormattedValue: ("value",), A.JoinedStr: ("values",),
    A.Yield: ("value",), A.YieldFrom: ("value",), A.Constant: (), A.Attribute: ("value",), A.Subscript: ("value", "slice"), A.Starred: ("value",),
    A.Name: (), A.List: ("elts",), A.Tuple: ("elts",), A.Slice: ("lower", "upper", "step"),
    A.comprehension: ("target", "iter", "ifs"),
    A.arguments: ("posonlyargs", "args", "vararg", "kwonlyargs", "kw_defaults", "kwarg", "defaults"),
    A.arg: ("annotation",), A.keyword: ("value",),
}
WHAT = {
    A.With: "with (context managers open files and locks)", A.AsyncWith: "async with", A.TryStar: "try/except*",
    A.Await: "await",
    A.AsyncFunctionDef: "async def", A.AsyncFor: "async for",
    A.Match: "match (class patterns read attributes by name)",
}
