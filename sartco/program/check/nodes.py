"""The check and the instrumentation of each node type, applied by instrument.py's walk.

Rules (RULES) check a node itself and instrument it in place; wraps (WRAPS) replace a child by
its instrumented form. Helpers live under names starting with `$`, which no Python source can
spell, so a program can neither reach nor shadow them:
- `$t()` (a C-level counter that raises StopIteration when the step budget is spent) at the top
  of every loop body and function body, in front of every lambda body, and as the first
  condition of every comprehension `for`;
- `a + b`, `a * b`, `a ** b`, `a << b`, `a % b` (and their augmented forms) become checked
  calls that refuse to build too-long sequences or too-large integers (and printf-style `%`
  formatting with widths above three digits); `a + 1`, `1 + a`, `a += 1` (an int constant
  of at most 64 bits, or a float) stay plain: they make a number one bit longer at most, or fail
  with TypeError, and never a sequence;
- `x.m` becomes `$attr(x, 'm')`, a store or del `x.m = v` `$fields(x, 'm')['m'] = v` (the rule is
  attributes.py's), f-strings `$len(f'...')`, displays with `*x` `$len([...])`;
- f-string format specs: a constant one has numbers of at most three digits, a computed one is
  checked when it runs (`$fstr`);
- every `except` handler starts with `$caught(<the exception>)`, which raises budget stops and
  refusals again (a program catches its own errors, never the sandbox's);
- every `finally` body starts with `$final()`, which remembers a RecursionError or MemoryError
  passing through (a `return`, `break` or `continue` there would swallow it) as the program's stop;
- a `match` value pattern's dotted name and a class pattern's class become attributes of
  `$pattern` (matching.py).
The checks of names and the walk's record are walk.py's.
"""
from __future__ import annotations

import ast

from .allowed import FIELDS, PROVIDED
from .matching import MATCH_RULES
from .walk import check_attribute_name, check_name, fail, located
from ..standins.classes import DATA, DEFINABLE, mangle_private
from ..standins.formatting import LONG_NUMBER, SPEC_DIGITS
from ..standins.modules import MEMBERS, refusal

CHECKED_OPS = {ast.Add: "$add", ast.Mult: "$mul", ast.Pow: "$pow", ast.LShift: "$lshift", ast.Mod: "$mod"}
INPLACE_OPS = {ast.Add: "$iadd", ast.Mult: "$imul", ast.Pow: "$ipow", ast.LShift: "$ilshift", ast.Mod: "$imod"}


_LOAD = ast.Load()


def _call(helper: str, args: list, old) -> ast.Call:
    at = {"lineno": old.lineno, "col_offset": old.col_offset,
          "end_lineno": old.end_lineno, "end_col_offset": old.end_col_offset}
    return ast.Call(ast.Name(helper, _LOAD, **at), args, [], **at)


def _tick(old) -> ast.Expr:
    return located(ast.Expr(_call("$t", [], old)), old)


# --- rules: checks (and in-place instrumentation) of a node itself ---------------------------

def _r_arg(n, walk):
    check_name(n, n.arg, True, walk)


def _r_keyword(n, walk):
    if n.arg is not None and n.arg[:2] == "__":
        fail(n, f"keyword arguments starting with two underscores are not allowed: {n.arg}")


def _r_function(n, walk):
    if id(n) not in walk.methods:
        check_name(n, n.name, True, walk)
    n.body.insert(0, _tick(n.body[0]))


def _r_class(n, walk):
    """A class statement (classes.py builds it): no keywords, `object` as a base is implied,
    and its defs and assignments (`__rmul__ = __mul__`) may bind DEFINABLE dunders (read anywhere)."""
    check_name(n, n.name, True, walk)
    if n.keywords and [k.arg for k in n.keywords] != ["metaclass"]:  # metaclass=: only abc's ABCMeta (records.py)
        fail(n, f"class {n.name}: class keywords (metaclass=...) are not allowed (a metaclass reaches the interpreter)")
    n.bases = [b for b in n.bases if not (type(b) is ast.Name and b.id == "object" and "object" not in walk.stored)]
    for statement in n.body:
        if type(statement) is ast.FunctionDef and statement.name in DEFINABLE:
            walk.methods.add(id(statement))
        elif type(statement) is ast.FunctionDef and statement.name in PROVIDED:  # a method `put`: the
            walk.methods.add(id(statement))  # class's name, not the program's (`robot.put(...)`)
            walk.stored.add(statement.name)
        elif type(statement) is ast.Assign:  # `__rmul__ = __mul__`, `__slots__ = ("x", "y")`
            walk.methods.update(id(t) for t in statement.targets
                                if type(t) is ast.Name and (t.id in DEFINABLE or t.id in DATA))
    mangle_private(n)


def _r_loop(n, walk):
    n.body.insert(0, _tick(n.body[0]))


def _r_lambda(n, walk):
    n.body = located(ast.BoolOp(ast.And(), [_call("$t", [], n.body), n.body]), n.body)


def _r_comprehension(n, walk):
    if n.is_async:
        fail(n.iter, "async comprehensions are not allowed")
    n.ifs.insert(0, _call("$t", [], n.iter))


def _r_formatted(n, walk):
    """A constant spec is checked here, a computed one (f'{x:>{w}}') when it runs; every field
    becomes f'{$fstr(x, conversion, spec)}' (its text relabelled: no address, conversions.py)."""
    spec = n.format_spec
    if spec is None:
        spec = ast.copy_location(ast.Constant(""), n)
    parts = spec.values if type(spec) is ast.JoinedStr else [spec]
    if all(type(part) is ast.Constant for part in parts):
        for part in parts:
            if LONG_NUMBER.search(str(part.value)):
                fail(n, f"f-string format widths and precisions above {'9' * SPEC_DIGITS} are not allowed")
    n.value = _call("$fstr", [n.value, located(ast.Constant(n.conversion), n), spec], n)
    n.conversion, n.format_spec = -1, None


def _r_handler(n, walk):
    """Every handler first hands what it caught to $caught, which raises it again if it is a
    budget stop or a refusal: a program may catch its own errors, never the sandbox's."""
    if n.name is None:
        n.name = "$e"
    else:
        check_name(n, n.name, True, walk)
    n.body.insert(0, located(ast.Expr(_call("$caught", [located(ast.Name(n.name, _LOAD), n)], n)), n.body[0]))


def _r_try(n, walk):
    """A `finally` body first calls $final, which remembers a depth or memory stop passing through:
    a `return`, `break` or `continue` in the body would end it, and the stop must stay the verdict."""
    if n.finalbody:
        n.finalbody.insert(0, located(ast.Expr(_call("$final", [], n.finalbody[0])), n.finalbody[0]))


def _r_scope(n, walk):  # global, nonlocal
    for name in n.names:
        check_name(n, name, True, walk)


def _r_import(n, walk):
    for alias in n.names:
        if alias.name not in MEMBERS:
            fail(n, refusal(alias.name))
        check_name(n, (alias.asname or alias.name).partition(".")[0], True, walk)
        walk.modules[alias.asname or alias.name] = alias.name


def _r_import_from(n, walk):
    module = n.module or ""
    if n.level or module not in MEMBERS or (module == "__future__" and n.names[0].name != "annotations"):
        fail(n, refusal("." * n.level + module))
    for alias in n.names:
        if alias.name == "*":
            walk.stored.update(MEMBERS[module])
        elif alias.name not in MEMBERS[module]:
            fail(n, f"{module}.{alias.name} is not available in the sandbox "
                    f"(available: {', '.join(sorted(MEMBERS[module]))})")
        else:
            check_name(n, alias.asname or alias.name, True, walk)


RULES = {
    ast.arg: _r_arg, ast.keyword: _r_keyword, ast.FunctionDef: _r_function,
    ast.For: _r_loop, ast.While: _r_loop, ast.Lambda: _r_lambda, ast.comprehension: _r_comprehension,
    ast.FormattedValue: _r_formatted, ast.ExceptHandler: _r_handler, ast.Try: _r_try, ast.Global: _r_scope, ast.Nonlocal: _r_scope,
    ast.Import: _r_import, ast.ImportFrom: _r_import_from, ast.ClassDef: _r_class,
    **MATCH_RULES,
}


# --- wraps: a child replaced by its instrumented form -----------------------------------------

def _w_attribute(n, wrapped, walk):
    """attributes.py's rule, before running: reads become $attr(x, 'm'), stores (and dels)
    $fields(x, 'm')['m'] (_check_attribute_name first)."""
    check_attribute_name(n, walk)
    key = located(ast.Constant(n.attr), n)
    wrapped.add(id(key))  # ours: not one of the program's strings (Walk.strings)
    if type(n.ctx) is not ast.Load:
        return located(ast.Subscript(_call("$fields", [n.value, key], n), key, n.ctx), n)
    return _call("$attr", [n.value, key], n)


def _small_number(node) -> bool:
    """A constant int (not bool) or float of at most 64 bits: adding it to anything gives a
    number at most one bit longer, or a TypeError; it can never build a sequence."""
    if type(node) is not ast.Constant:
        return False
    t = type(node.value)
    return t is float or (t is int and -(1 << 64) < node.value < (1 << 64))


def _w_binop(n, wrapped, walk):
    op = type(n.op)
    helper = CHECKED_OPS.get(op)
    if helper is None or (op is ast.Add and (_small_number(n.right) or _small_number(n.left))):
        return n
    return _call(helper, [n.left, n.right], n)


def _w_augassign(n, wrapped, walk):
    if type(n.target) is ast.Attribute:  # obj.m op= v: on $fields(obj, 'm')['m']
        n.target = _w_attribute(n.target, wrapped, walk)
    target, op = n.target, type(n.op)
    helper = INPLACE_OPS.get(op)
    if helper is None or (op is ast.Add and _small_number(n.value)):
        return n
    if type(target) is ast.Name:
        load = located(ast.Name(target.id, ast.Load()), target)
        return located(ast.Assign([target], _call(helper, [load, n.value], n)), n)
    if type(target) is ast.Subscript:
        key = target.slice
        if type(key) is ast.Slice:
            none = located(ast.Constant(None), key)
            key = _call("$slice", [key.lower or none, key.upper or none, key.step or none], key)
        args = [target.value, key, located(ast.Name(helper, ast.Load()), n), n.value]
        return located(ast.Expr(_call("$iitem", args, n)), n)
    fail(n, "augmented assignment to this target is not allowed")


# a node wrapped in $len is visited again as the wrapper's argument: `wrapped` remembers it
def _w_joined(n, wrapped, walk):
    if id(n) in wrapped:
        return n
    wrapped.add(id(n))
    return _call("$len", [n], n)


def _w_display(n, wrapped, walk):
    if type(getattr(n, "ctx", _LOAD)) is not ast.Load or ast.Starred not in map(type, n.elts) or id(n) in wrapped:
        return n
    wrapped.add(id(n))
    return _call("$len", [n], n)


# every wrap, called as wrap(node, wrapped, walk)
WRAPS = {
    ast.Attribute: _w_attribute, ast.BinOp: _w_binop, ast.AugAssign: _w_augassign,
    ast.JoinedStr: _w_joined, ast.List: _w_display, ast.Tuple: _w_display, ast.Set: _w_display,
}


def _is_list_field(t: type, field: str) -> bool:
    """Whether a field of node type t holds a list of nodes (from the grammar: `*` fields)."""
    if t in (ast.Lambda, ast.IfExp):
        return False
    return field in {
        "body", "targets", "orelse", "values", "elts", "keys", "generators", "comparators",
        "keywords", "ifs", "posonlyargs", "kwonlyargs", "kw_defaults", "defaults", "handlers", "finalbody",
        "decorator_list", "bases", "items", "cases", "patterns", "kwd_patterns",
    } or (field == "args" and t in (ast.Call, ast.arguments))


# per allowed node type: (rule or None, ((field, whether it holds a list of nodes), ...))
PLAN: dict[type, tuple] = {t: (RULES.get(t), tuple((f, _is_list_field(t, f)) for f in fs)) for t, fs in FIELDS.items()}
