"""The subset of Python a program may use, as data: the builtins, the attribute names, the
syntax node types (with the fields that hold their children) and why the others are refused.

Allowed: every statement and expression of Python except async/await and try/except*
(see WHAT for why; `match` with its value and class patterns read through the attribute rule:
patterns.py); `with` too, whose context managers can only be the stand-ins that offer
them (contextlib's suppress and nullcontext: a program's class cannot define `__enter__`), none
of which swallows a budget stop; class statements as classes.py builds them; imports of the
stand-in modules of modules.py only; any name except those starting with two underscores (but
`__name__` may be read: `if __name__ == "__main__":`), `put`/`init_board` never rebound, and a
builtin outside ALLOWED_BUILTINS only if the program binds that name itself (`type = 'nut'`);
attributes as attributes.py rules (ATTRIBUTES: the names the sandbox offers).
"""
from __future__ import annotations

import ast
import builtins

from ..standins.attributes import OFFERED, RECORD_NAMES, TYPES
from ..standins.classes import EXCEPTIONS
from ..standins.methods import METHODS
from ..standins.modules import MEMBERS

ALLOWED_BUILTINS = frozenset(
    "range zip enumerate len min max abs sum sorted reversed any all round divmod "
    "int str bool list tuple dict set frozenset float print isinstance issubclass map filter next iter "
    "chr ord pow format repr ascii hex bin oct callable hash slice super property staticmethod classmethod type "
    "NotImplemented Ellipsis".split()
) | EXCEPTIONS
PROVIDED = frozenset({"put", "init_board"})  # `board` is provided too, but may be rebound
DENIED = frozenset(dir(builtins)) - ALLOWED_BUILTINS - {"True", "False", "None", "Ellipsis", "NotImplemented", "__name__"}
# every attribute name the sandbox offers (a program may also read the names it defines)
ATTRIBUTES = METHODS.union(*MEMBERS.values(), *TYPES.values(), RECORD_NAMES, OFFERED)


# the fields of each allowed node type that hold child nodes; a type not listed is forbidden
FIELDS: dict[type, tuple[str, ...]] = {
    ast.Module: ("body",), ast.ClassDef: ("decorator_list", "bases", "body"), ast.FunctionDef: ("decorator_list", "args", "body", "returns"), ast.Return: ("value",),
    ast.Assign: ("targets", "value"), ast.AugAssign: ("target", "value"),
    ast.AnnAssign: ("target", "annotation", "value"), ast.Delete: ("targets",),
    ast.For: ("target", "iter", "body", "orelse"), ast.While: ("test", "body", "orelse"),
    ast.If: ("test", "body", "orelse"), ast.Expr: ("value",), ast.Pass: (), ast.Break: (), ast.Continue: (),
    ast.Try: ("body", "handlers", "orelse", "finalbody"), ast.ExceptHandler: ("type", "body"),
    ast.With: ("items", "body"), ast.withitem: ("context_expr", "optional_vars"),
    ast.Raise: ("exc", "cause"), ast.Assert: ("test", "msg"), ast.Global: (), ast.Nonlocal: (),
    ast.Import: (), ast.ImportFrom: (),
    ast.BoolOp: ("values",), ast.NamedExpr: ("target", "value"), ast.BinOp: ("left", "right"),
    ast.UnaryOp: ("operand",), ast.Lambda: ("args", "body"), ast.IfExp: ("test", "body", "orelse"),
    ast.Dict: ("keys", "values"), ast.Set: ("elts",), ast.ListComp: ("elt", "generators"),
    ast.SetComp: ("elt", "generators"), ast.GeneratorExp: ("elt", "generators"),
    ast.DictComp: ("key", "value", "generators"), ast.Compare: ("left", "comparators"),
    ast.Call: ("func", "args", "keywords"), ast.FormattedValue: ("value",), ast.JoinedStr: ("values",),
    ast.Yield: ("value",), ast.YieldFrom: ("value",), ast.Constant: (), ast.Attribute: ("value",), ast.Subscript: ("value", "slice"), ast.Starred: ("value",),
    ast.Name: (), ast.List: ("elts",), ast.Tuple: ("elts",), ast.Slice: ("lower", "upper", "step"),
    ast.comprehension: ("target", "iter", "ifs"),
    ast.arguments: ("posonlyargs", "args", "vararg", "kwonlyargs", "kw_defaults", "kwarg", "defaults"),
    ast.arg: ("annotation",), ast.keyword: ("value",),
    # match: a value pattern's name and a class pattern's class are rewritten by their rules (nodes.py)
    ast.Match: ("subject", "cases"), ast.match_case: ("pattern", "guard", "body"),
    ast.MatchValue: (), ast.MatchSingleton: (), ast.MatchSequence: ("patterns",),
    ast.MatchMapping: ("patterns",), ast.MatchClass: ("patterns", "kwd_patterns"), ast.MatchStar: (),
    ast.MatchAs: ("pattern",), ast.MatchOr: ("patterns",),
}
WHAT = {
    ast.AsyncWith: "async with", ast.TryStar: "try/except*",
    ast.Await: "await",
    ast.AsyncFunctionDef: "async def", ast.AsyncFor: "async for",
}
