"""Validate a program's syntax tree and instrument it for the budgets, in one pass.

Pure: nothing here runs model code. `prepare(source)` returns a code object or raises
`Forbidden` (a construct outside the allowed subset) / SyntaxError.

The check looks at the parsed tree, never at the text: the parser normalises full-width Unicode
identifiers (NFKC), so `ｅｖａｌ` arrives here as `eval`.

Allowed: the statements def (no decorators), return, assignments (plain, tuple, starred,
augmented), for, while, if, break, continue, pass and expression statements; the expressions
of the Python grammar except await/yield; names that do not start with an underscore and are
not one of Python's other builtins; attribute access only to call the methods in `METHODS`
(checked again at run time against the object's type).

Instrumentation (helpers live under names starting with `$`, which no Python source can spell,
so a program can neither reach nor shadow them):
- `$t()` (a C-level counter that raises StopIteration when the step budget is spent) at the top
  of every loop body and function body, in front of every lambda body, and as the first
  condition of every comprehension `for`;
- `a + b`, `a * b`, `a ** b`, `a << b`, `a % b` (and their augmented forms) become checked
  calls that refuse to build too-long sequences or too-large integers, and refuse printf-style
  `%` formatting (its widths are a memory bomb); `a + 1`, `1 + a`, `a += 1` (an int constant
  of at most 64 bits, or a float) stay plain: they make a number one bit longer at most, or fail
  with TypeError, and never a sequence;
- `x.m` becomes `$attr(x, 'm')`, f-strings `$len(f'...')`, displays with `*x` `$len([...])`;
- f-string format specs must be constant, with numbers of at most three digits.
"""
from __future__ import annotations

import ast
import builtins
import re

__all__ = ["ALLOWED_BUILTINS", "METHODS", "PROVIDED", "TYPE_METHODS", "Forbidden", "prepare"]

ALLOWED_BUILTINS = frozenset(
    "range zip enumerate len min max abs sum sorted reversed any all round divmod "
    "int str bool list tuple dict set print".split()
)
PROVIDED = frozenset({"put", "init_board"})  # `board` is provided too, but may be rebound
PROTECTED = ALLOWED_BUILTINS | PROVIDED
DENIED = frozenset(dir(builtins)) - ALLOWED_BUILTINS - {"True", "False", "None"}
TYPE_METHODS = {  # the methods a program may call, per type (checked again at run time)
    list: frozenset({"append", "extend", "insert", "pop", "index", "count"}),
    dict: frozenset({"get", "items", "keys", "values", "pop"}),
    str: frozenset({"lower", "upper", "strip", "split", "index", "count"}),
    tuple: frozenset({"index", "count"}),
}
METHODS = frozenset().union(*TYPE_METHODS.values())
CHECKED_OPS = {ast.Add: "$add", ast.Mult: "$mul", ast.Pow: "$pow", ast.LShift: "$lshift", ast.Mod: "$mod"}
INPLACE_OPS = {ast.Add: "$iadd", ast.Mult: "$imul", ast.Pow: "$ipow", ast.LShift: "$ilshift", ast.Mod: "$imod"}

# the fields of each allowed node type that hold child nodes; a type not listed is forbidden
A = ast
FIELDS: dict[type, tuple[str, ...]] = {
    A.Module: ("body",), A.FunctionDef: ("args", "body", "returns"), A.Return: ("value",),
    A.Assign: ("targets", "value"), A.AugAssign: ("target", "value"),
    A.For: ("target", "iter", "body", "orelse"), A.While: ("test", "body", "orelse"),
    A.If: ("test", "body", "orelse"), A.Expr: ("value",), A.Pass: (), A.Break: (), A.Continue: (),
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
    A.Import: "import", A.ImportFrom: "import", A.ClassDef: "class", A.With: "with",
    A.AsyncWith: "async with", A.Try: "try", A.TryStar: "try", A.Global: "global",
    A.Nonlocal: "nonlocal", A.Yield: "yield", A.YieldFrom: "yield from", A.Await: "await",
    A.AsyncFunctionDef: "async def", A.AsyncFor: "async for", A.Delete: "del", A.Raise: "raise",
    A.Assert: "assert", A.Match: "match", A.AnnAssign: "annotated assignment",
}
_SPEC_NUMBER = re.compile(r"\d+")


class Forbidden(Exception):
    """A construct outside the allowed subset (found before running, or at run time)."""

    position = (0, 0)


def _fail(node, text: str):
    line = getattr(node, "lineno", None)
    exc = Forbidden(f"line {line}: {text}" if line else text)
    exc.position = (line or 0, getattr(node, "col_offset", 0))
    raise exc


def _name(node, name: str, store: bool):
    if name[0] == "$":  # ours: no Python source can spell it
        return
    if name[0] == "_":
        _fail(node, f"names starting with an underscore are not allowed: {name}")
    if name in DENIED:
        _fail(node, f"{name} is not available (allowed builtins: {', '.join(sorted(ALLOWED_BUILTINS))})")
    if store and name in PROTECTED:
        _fail(node, f"{name} cannot be redefined")


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

def _r_arg(n):
    _name(n, n.arg, True)


def _r_keyword(n):
    if n.arg is not None and n.arg[0] == "_":
        _fail(n, f"keyword arguments starting with an underscore are not allowed: {n.arg}")


def _r_function(n):
    if n.decorator_list:
        _fail(n, "decorators are not allowed")
    _name(n, n.name, True)
    n.body.insert(0, _tick(n.body[0]))


def _r_loop(n):
    n.body.insert(0, _tick(n.body[0]))


def _r_lambda(n):
    n.body = _loc(ast.BoolOp(ast.And(), [_call("$t", [], n.body), n.body]), n.body)


def _r_comprehension(n):
    if n.is_async:
        _fail(n.iter, "async comprehensions are not allowed")
    n.ifs.insert(0, _call("$t", [], n.iter))


def _r_formatted(n):
    spec = n.format_spec
    if spec is None:
        return
    parts = spec.values if type(spec) is ast.JoinedStr else [spec]
    for part in parts:
        if type(part) is not ast.Constant or type(part.value) is not str:
            _fail(n, "f-string format specs must be constant")
        if any(len(number) > 3 for number in _SPEC_NUMBER.findall(part.value)):
            _fail(n, "f-string format widths and precisions above 999 are not allowed")


RULES = {
    A.arg: _r_arg, A.keyword: _r_keyword, A.FunctionDef: _r_function,
    A.For: _r_loop, A.While: _r_loop, A.Lambda: _r_lambda, A.comprehension: _r_comprehension,
    A.FormattedValue: _r_formatted,
}


# --- wraps: a child replaced by its instrumented form -----------------------------------------

def _w_attribute(n, wrapped):
    if type(n.ctx) is not ast.Load:
        _fail(n, f"assigning to an attribute (.{n.attr}) is not allowed")
    if n.attr[0] == "_":
        _fail(n, f"attributes starting with an underscore are not allowed: .{n.attr}")
    if n.attr not in METHODS:
        _fail(n, f"attribute .{n.attr} is not allowed (allowed methods: {', '.join(sorted(METHODS))})")
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
    if type(n.ctx) is not ast.Load or ast.Starred not in map(type, n.elts) or id(n) in wrapped:
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
        "keywords", "ifs", "posonlyargs", "kwonlyargs", "kw_defaults", "defaults",
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
                rule(node)
            for field, many in fields:
                value = getattr(node, field)
                for child in value if many else (value,):
                    ct = type(child)
                    if ct is const_type or child is None:
                        continue
                    if ct is name_type:
                        if type(child.ctx) is not load_type:
                            _name(child, child.id, True)
                        elif child.id not in seen_loads:
                            _name(child, child.id, False)
                            seen_loads.add(child.id)
                        continue
                    wrap = wrap_of(ct)
                    if wrap is not None:
                        new = wrap(child, wrapped)
                        if new is not child:
                            if many:
                                value[value.index(child)] = new  # nodes compare by identity
                            else:
                                setattr(node, field, new)
                            child = new
                    push(child)
        except Forbidden as exc:
            offences.append(exc)
    if offences:
        raise min(offences, key=lambda exc: exc.position)
    return tree


def prepare(source: str):
    """Parse, check and instrument; return a code object. Raises SyntaxError or Forbidden."""
    tree = compile(source, "<program>", "exec", ast.PyCF_ONLY_AST, dont_inherit=True)
    return compile(instrument(tree), "<program>", "exec", dont_inherit=True)
