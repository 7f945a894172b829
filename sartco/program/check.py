"""Validate a program's syntax tree and instrument it for the budgets, in one pass.

Pure: nothing here runs model code. `prepare(source)` returns a code object or raises
`Forbidden` (a construct outside the allowed subset) / SyntaxError.

The check looks at the parsed tree, never at the text: the parser normalises full-width Unicode
identifiers (NFKC), so `ｅｖａｌ` arrives here as `eval`.

Allowed: every statement and expression of Python except class, with, yield, async/await,
match and try/except* (see WHAT for why); imports of the stand-in modules of modules.py only;
any name except those starting with two underscores, `put`/`init_board` never rebound, and a
builtin outside ALLOWED_BUILTINS only if the program binds that name itself (`type = 'nut'`);
attribute reads of the names in ATTRIBUTES only (the methods of TYPE_METHODS and the stand-in
modules' members, checked again at run time against the object's type), never a store.

Instrumentation (helpers live under names starting with `$`, which no Python source can spell,
so a program can neither reach nor shadow them):
- `$t()` (a C-level counter that raises StopIteration when the step budget is spent) at the top
  of every loop body and function body, in front of every lambda body, and as the first
  condition of every comprehension `for`;
- `a + b`, `a * b`, `a ** b`, `a << b`, `a % b` (and their augmented forms) become checked
  calls that refuse to build too-long sequences or too-large integers (and printf-style `%`
  formatting with widths above three digits); `a + 1`, `1 + a`, `a += 1` (an int constant
  of at most 64 bits, or a float) stay plain: they make a number one bit longer at most, or fail
  with TypeError, and never a sequence;
- `x.m` becomes `$attr(x, 'm')`, f-strings `$len(f'...')`, displays with `*x` `$len([...])`;
- f-string format specs: a constant one has numbers of at most three digits, a computed one is
  checked when it runs (`$fstr`);
- every `except` handler starts with `$caught(<the exception>)`, which raises budget stops and
  refusals again (a program catches its own errors, never the sandbox's).
The walk is one linear pass over the tree (no search inside lists: a 100 KB display checks in
about the time compile() takes).
"""
from __future__ import annotations

import ast
import builtins
import collections
import re

from .budget import SPEC_DIGITS, Forbidden
from .modules import MEMBERS, refusal

__all__ = ["ALLOWED_BUILTINS", "ATTRIBUTES", "DENIED", "METHODS", "PROVIDED", "TYPE_METHODS", "Forbidden", "prepare"]

EXCEPTIONS = frozenset(
    "Exception BaseException ValueError TypeError KeyError IndexError ZeroDivisionError ArithmeticError "
    "LookupError AttributeError RuntimeError StopIteration AssertionError NotImplementedError OverflowError "
    "NameError UnboundLocalError".split()
)
ALLOWED_BUILTINS = frozenset(
    "range zip enumerate len min max abs sum sorted reversed any all round divmod "
    "int str bool list tuple dict set frozenset float print isinstance issubclass map filter next iter "
    "chr ord pow format repr ascii hex bin oct callable hash slice".split()
) | EXCEPTIONS
PROVIDED = frozenset({"put", "init_board"})  # `board` is provided too, but may be rebound
DENIED = frozenset(dir(builtins)) - ALLOWED_BUILTINS - {"True", "False", "None", "Ellipsis", "NotImplemented"}
_LIST = frozenset({"append", "extend", "insert", "pop", "index", "count", "remove", "reverse", "sort", "copy",
                   "clear"})
_DICT = frozenset({"get", "items", "keys", "values", "pop", "update", "setdefault", "copy", "clear", "popitem"})
_FROZEN = frozenset({"union", "intersection", "difference", "symmetric_difference", "issubset", "issuperset",
                     "isdisjoint", "copy"})
_SET = _FROZEN | {"add", "update", "discard", "remove", "pop", "clear", "intersection_update",
                  "difference_update", "symmetric_difference_update"}
_STR = frozenset({
    "lower", "upper", "title", "capitalize", "swapcase", "casefold", "strip", "lstrip", "rstrip", "split",
    "rsplit", "splitlines", "partition", "rpartition", "join", "replace", "startswith", "endswith", "find",
    "rfind", "index", "rindex", "count", "format", "format_map", "center", "ljust", "rjust", "zfill",
    "isdigit", "isalpha", "isalnum", "isspace", "isupper", "islower", "isnumeric", "isdecimal", "istitle",
    "removeprefix", "removesuffix"})
TYPE_METHODS = {  # the methods a program may call, per type (checked again at run time)
    list: _LIST, dict: _DICT, str: _STR, set: _SET, frozenset: _FROZEN,
    tuple: frozenset({"index", "count"}),
    collections.defaultdict: _DICT, collections.OrderedDict: _DICT,
    collections.Counter: _DICT | {"most_common", "elements", "subtract", "total"},
    collections.deque: frozenset({"append", "appendleft", "pop", "popleft", "extend", "extendleft", "rotate",
                                  "index", "count", "remove", "reverse", "copy", "clear", "insert"}),
}
METHODS = frozenset().union(*TYPE_METHODS.values())
ATTRIBUTES = METHODS.union(*MEMBERS.values())  # every attribute name a program may read
CHECKED_OPS = {ast.Add: "$add", ast.Mult: "$mul", ast.Pow: "$pow", ast.LShift: "$lshift", ast.Mod: "$mod"}
INPLACE_OPS = {ast.Add: "$iadd", ast.Mult: "$imul", ast.Pow: "$ipow", ast.LShift: "$ilshift", ast.Mod: "$imod"}

# the fields of each allowed node type that hold child nodes; a type not listed is forbidden
A = ast
FIELDS: dict[type, tuple[str, ...]] = {
    A.Module: ("body",), A.FunctionDef: ("decorator_list", "args", "body", "returns"), A.Return: ("value",),
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
    A.Constant: (), A.Attribute: ("value",), A.Subscript: ("value", "slice"), A.Starred: ("value",),
    A.Name: (), A.List: ("elts",), A.Tuple: ("elts",), A.Slice: ("lower", "upper", "step"),
    A.comprehension: ("target", "iter", "ifs"),
    A.arguments: ("posonlyargs", "args", "vararg", "kwonlyargs", "kw_defaults", "kwarg", "defaults"),
    A.arg: ("annotation",), A.keyword: ("value",),
}
WHAT = {
    A.ClassDef: "class (a class needs dunder methods, which reach the interpreter)",
    A.With: "with (context managers open files and locks)", A.AsyncWith: "async with", A.TryStar: "try/except*",
    A.Yield: "yield (generator frames reach the interpreter)", A.YieldFrom: "yield from", A.Await: "await",
    A.AsyncFunctionDef: "async def", A.AsyncFor: "async for",
    A.Match: "match (class patterns read attributes by name)",
}
_SPEC_NUMBER = re.compile(r"\d+")


def _fail(node, text: str):
    line = getattr(node, "lineno", None)
    exc = Forbidden(f"line {line}: {text}" if line else text)
    exc.position = (line or 0, getattr(node, "col_offset", 0))
    raise exc


class _Walk:
    """What one walk has seen: names the program binds, builtins it reads that are not there."""

    __slots__ = ("stored", "denied")

    def __init__(self):
        self.stored: set[str] = set()
        self.denied: dict[str, ast.AST] = {}


def _name(node, name: str, store: bool, walk: _Walk):
    if name[0] == "$":  # ours: no Python source can spell it
        return
    if name[0] == "_" and name[:2] == "__":
        _fail(node, f"names starting with two underscores reach the interpreter: {name}")
    if store:
        if name in PROVIDED:
            _fail(node, f"{name} is the task's world and cannot be redefined")
        walk.stored.add(name)
    elif name in DENIED and name not in walk.denied:
        walk.denied[name] = node  # refused at the end unless the program binds the name itself


def _loc(new, old):
    new.lineno = old.lineno
    new.col_offset = old.col_offset
    new.end_lineno = old.end_lineno
    new.end_col_offset = old.end_col_offset
    return new


_LOAD = ast.Load()


def _call(helper: str, args: list, old) -> ast.Call:
    at = {"lineno": old.lineno, "col_offset": old.col_offset,
          "end_lineno": old.end_lineno, "end_col_offset": old.end_col_offset}
    return ast.Call(ast.Name(helper, _LOAD, **at), args, [], **at)


def _tick(old) -> ast.Expr:
    return _loc(ast.Expr(_call("$t", [], old)), old)


# --- rules: checks (and in-place instrumentation) of a node itself ---------------------------

def _r_arg(n, walk):
    _name(n, n.arg, True, walk)


def _r_keyword(n, walk):
    if n.arg is not None and n.arg[:2] == "__":
        _fail(n, f"keyword arguments starting with two underscores are not allowed: {n.arg}")


def _r_function(n, walk):
    _name(n, n.name, True, walk)
    n.body.insert(0, _tick(n.body[0]))


def _r_loop(n, walk):
    n.body.insert(0, _tick(n.body[0]))


def _r_lambda(n, walk):
    n.body = _loc(ast.BoolOp(ast.And(), [_call("$t", [], n.body), n.body]), n.body)


def _r_comprehension(n, walk):
    if n.is_async:
        _fail(n.iter, "async comprehensions are not allowed")
    n.ifs.insert(0, _call("$t", [], n.iter))


def _r_formatted(n, walk):
    """A constant spec is checked here; a computed one (f'{x:>{w}}') is checked when it runs:
    the field becomes f'{$fstr(x, conversion, spec)}'."""
    spec = n.format_spec
    if spec is None:
        return
    parts = spec.values if type(spec) is ast.JoinedStr else [spec]
    if all(type(part) is ast.Constant for part in parts):
        for part in parts:
            if any(len(number) > SPEC_DIGITS for number in _SPEC_NUMBER.findall(str(part.value))):
                _fail(n, f"f-string format widths and precisions above {'9' * SPEC_DIGITS} are not allowed")
        return
    n.value = _call("$fstr", [n.value, _loc(ast.Constant(n.conversion), n), spec], n)
    n.conversion, n.format_spec = -1, None


def _r_handler(n, walk):
    """Every handler first hands what it caught to $caught, which raises it again if it is a
    budget stop or a refusal: a program may catch its own errors, never the sandbox's."""
    if n.name is None:
        n.name = "$e"
    else:
        _name(n, n.name, True, walk)
    n.body.insert(0, _loc(ast.Expr(_call("$caught", [_loc(ast.Name(n.name, _LOAD), n)], n)), n.body[0]))


def _r_scope(n, walk):  # global, nonlocal
    for name in n.names:
        _name(n, name, True, walk)


def _r_import(n, walk):
    for alias in n.names:
        if alias.name not in MEMBERS:
            _fail(n, refusal(alias.name))
        _name(n, (alias.asname or alias.name).partition(".")[0], True, walk)


def _r_import_from(n, walk):
    module = n.module or ""
    if n.level or module not in MEMBERS:
        _fail(n, refusal("." * n.level + module))
    for alias in n.names:
        if alias.name == "*":
            walk.stored.update(MEMBERS[module])
        elif alias.name not in MEMBERS[module]:
            _fail(n, f"{module}.{alias.name} is not available in the sandbox "
                     f"(available: {', '.join(sorted(MEMBERS[module]))})")
        else:
            _name(n, alias.asname or alias.name, True, walk)


RULES = {
    A.arg: _r_arg, A.keyword: _r_keyword, A.FunctionDef: _r_function,
    A.For: _r_loop, A.While: _r_loop, A.Lambda: _r_lambda, A.comprehension: _r_comprehension,
    A.FormattedValue: _r_formatted, A.ExceptHandler: _r_handler, A.Global: _r_scope, A.Nonlocal: _r_scope,
    A.Import: _r_import, A.ImportFrom: _r_import_from,
}


# --- wraps: a child replaced by its instrumented form -----------------------------------------

def _w_attribute(n, wrapped):
    if type(n.ctx) is not ast.Load:
        _fail(n, f"assigning to an attribute (.{n.attr}) is not allowed")
    if n.attr[0] == "_":
        _fail(n, f"attributes starting with an underscore reach the interpreter: .{n.attr}")
    if n.attr not in ATTRIBUTES:
        _fail(n, f"attribute .{n.attr} is not available in the sandbox (only the common methods of "
                 f"str, list, dict, set and tuple, and the members of the allowed modules)")
    return _call("$attr", [n.value, _loc(ast.Constant(n.attr), n)], n)


def _small_number(node) -> bool:
    """A constant int (not bool) or float of at most 64 bits: adding it to anything gives a
    number at most one bit longer, or a TypeError; it can never build a sequence."""
    if type(node) is not ast.Constant:
        return False
    t = type(node.value)
    return t is float or (t is int and -(1 << 64) < node.value < (1 << 64))


def _w_binop(n, wrapped):
    op = type(n.op)
    helper = CHECKED_OPS.get(op)
    if helper is None or (op is ast.Add and (_small_number(n.right) or _small_number(n.left))):
        return n
    return _call(helper, [n.left, n.right], n)


def _w_augassign(n, wrapped):
    target, op = n.target, type(n.op)
    if type(target) is ast.Attribute:
        _fail(n, f"assigning to an attribute (.{target.attr}) is not allowed")
    helper = INPLACE_OPS.get(op)
    if helper is None or (op is ast.Add and _small_number(n.value)):
        return n
    if type(target) is ast.Name:
        load = _loc(ast.Name(target.id, ast.Load()), target)
        return _loc(ast.Assign([target], _call(helper, [load, n.value], n)), n)
    if type(target) is ast.Subscript:
        key = target.slice
        if type(key) is ast.Slice:
            none = _loc(ast.Constant(None), key)
            key = _call("$slice", [key.lower or none, key.upper or none, key.step or none], key)
        args = [target.value, key, _loc(ast.Name(helper, ast.Load()), n), n.value]
        return _loc(ast.Expr(_call("$iitem", args, n)), n)
    _fail(n, "augmented assignment to this target is not allowed")


# a node wrapped in $len is visited again as the wrapper's argument: `wrapped` remembers it
def _w_joined(n, wrapped):
    if id(n) in wrapped:
        return n
    wrapped.add(id(n))
    return _call("$len", [n], n)


def _w_display(n, wrapped):
    if type(getattr(n, "ctx", _LOAD)) is not ast.Load or ast.Starred not in map(type, n.elts) or id(n) in wrapped:
        return n
    wrapped.add(id(n))
    return _call("$len", [n], n)


# every wrap, called as wrap(node, wrapped)
WRAPS = {
    A.Attribute: _w_attribute, A.BinOp: _w_binop, A.AugAssign: _w_augassign,
    A.JoinedStr: _w_joined, A.List: _w_display, A.Tuple: _w_display, A.Set: _w_display,
}


def _is_list_field(t: type, field: str) -> bool:
    """Whether a field of node type t holds a list of nodes (from the grammar: `*` fields)."""
    if t in (A.Lambda, A.IfExp):
        return False
    return field in {
        "body", "targets", "orelse", "values", "elts", "keys", "generators", "comparators",
        "keywords", "ifs", "posonlyargs", "kwonlyargs", "kw_defaults", "defaults", "handlers", "finalbody",
        "decorator_list",
    } or (field == "args" and t in (A.Call, A.arguments))


# per allowed node type: (rule or None, ((field, whether it holds a list of nodes), ...))
PLAN: dict[type, tuple] = {t: (RULES.get(t), tuple((f, _is_list_field(t, f)) for f in fs)) for t, fs in FIELDS.items()}


def instrument(tree: ast.Module) -> ast.Module:
    """Check every node and instrument in place; raise the Forbidden that comes first in the text.

    One iterative pass (no recursion limit to hit); leaves (names, constants) are handled
    where they are met, because they make up two thirds of a typical tree. After an offence the
    walk goes on (without the offending node's remaining children), so that the offence
    reported is the first one in the source, not the first one visited."""
    todo = [tree]
    pop, push = todo.pop, todo.append
    wrapped: set[int] = set()
    seen_loads: set[str] = set()  # names already checked in a load context
    offences: list[Forbidden] = []
    walk = _Walk()
    plan_of, wrap_of, name_type, const_type, load_type = PLAN.get, WRAPS.get, ast.Name, ast.Constant, ast.Load

    while todo:
        node = pop()
        try:
            t = type(node)
            plan = plan_of(t)
            if plan is None:
                _fail(node, f"{WHAT.get(t) or t.__name__} is not allowed")
            rule, fields = plan
            if rule is not None:
                rule(node, walk)
            for field, many in fields:
                value = getattr(node, field)
                k = 0  # where the last replaced child was: each list is searched once, in order
                for child in value if many else (value,):
                    ct = type(child)
                    if ct is const_type or child is None:
                        continue
                    if ct is name_type:
                        if type(child.ctx) is not load_type:
                            _name(child, child.id, True, walk)
                        elif child.id not in seen_loads:
                            _name(child, child.id, False, walk)
                            seen_loads.add(child.id)
                        continue
                    wrap = wrap_of(ct)
                    if wrap is not None:
                        new = wrap(child, wrapped)
                        if new is not child:
                            if many:
                                k = value.index(child, k)  # nodes compare by identity
                                value[k] = new
                            else:
                                setattr(node, field, new)
                            child = new
                    push(child)
        except Forbidden as exc:
            offences.append(exc)
    for name, node in walk.denied.items():
        if name not in walk.stored:
            try:
                _fail(node, f"{name} is not available in the sandbox: it reaches the interpreter, files or the "
                            f"terminal (builtins here: {', '.join(sorted(ALLOWED_BUILTINS - EXCEPTIONS))})")
            except Forbidden as exc:
                offences.append(exc)
    if offences:
        raise min(offences, key=lambda exc: exc.position)
    return tree


def prepare(source: str):
    """Parse, check and instrument; return a code object. Raises SyntaxError or Forbidden."""
    tree = compile(source, "<program>", "exec", ast.PyCF_ONLY_AST, dont_inherit=True)
    return compile(instrument(tree), "<program>", "exec", dont_inherit=True)
