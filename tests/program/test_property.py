"""Property: whatever goes in (random text, programs from a statement grammar, random syntax
trees), execute() returns an Execution with a known code and a canonical board, never raises.
Put-only programs must agree exactly with the world's own `put` applied directly.
Example counts stay modest: every example is a round trip to the worker.
"""
import ast

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from sartco.program import Execution, Limits, execute
from sartco.world import COLORS, MAX_DEPTH, SHAPES, Board, ErrorCode, WorldError, parse_key, put
from sartco.world.board import KEY, MAX_SIDE

LIMITS = Limits(steps=20_000, wall_time=20.0)
SETTINGS = settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])


def _assert_result(ex):
    assert type(ex) is Execution
    assert ex.error is None if ex.ok else isinstance(ex.error, ErrorCode)
    assert isinstance(ex.message, str) and type(ex.puts) is int
    assert type(ex.cells) is dict
    for key, stack in ex.cells.items():
        assert KEY.fullmatch(key)
        r, c = parse_key(key)
        assert 0 <= r < MAX_SIDE and 0 <= c < MAX_SIDE and 1 <= len(stack) <= MAX_DEPTH
        assert all(s in SHAPES and col in COLORS for s, col in stack)


# --- random text --------------------------------------------------------------------------------

@SETTINGS
@given(st.text(max_size=300))
def test_random_text(text):
    _assert_result(execute(text, limits=LIMITS))


@SETTINGS
@given(st.lists(st.sampled_from(
    ["put", "(", ")", "board", ",", "'washer'", "'red'", "1", "\n", " ", ":", "for", "in", "range",
     "def", "lambda", "if", "while", "=", "+", "*", "**", "[", "]", "{", "}", ".", "__class__",
     "append", "f'{", "}'", "import", "    ", "x", "return", "init_board", "not", "and", "-"]), max_size=40))
def test_random_tokens(tokens):
    _assert_result(execute("".join(tokens), limits=LIMITS))


# --- a statement grammar --------------------------------------------------------------------------

coordinate = st.one_of(st.integers(-2, 9), st.sampled_from(["x", "i", "n", "10**20", "'3'", "1.5", "True"]))
shape = st.one_of(st.sampled_from([repr(s) for s in SHAPES]), st.sampled_from(["'bolt'", "5", "shape", "None"]))
color = st.one_of(st.sampled_from([repr(c) for c in COLORS]), st.sampled_from(["'pink'", "color", "[]"]))
expr = st.one_of(st.integers(-5, 10).map(str), st.sampled_from(
    ["x", "i", "n", "x + 1", "n * 2", "len(L)", "L[0]", "L[-1]", "d.get('k', 0)", "x // 0", "abs(-x)",
     "[1, 2][x]", "'ab' * x", "sum(L)", "max(L)", "(lambda a: a + 1)(x)", "f(x)", "undefined_name"]))


def _put(args):
    s, c, x, y, kw = args
    return f"put(board, shape={s}, color={c}, x={x}, y={y})" if kw else f"put(board, {s}, {c}, {x}, {y})"


put_call = st.tuples(shape, color, coordinate, coordinate, st.booleans()).map(_put)
simple_stmt = st.one_of(
    put_call,
    expr.map(lambda e: f"x = {e}"), expr.map(lambda e: f"n = {e}"),
    expr.map(lambda e: f"L.append({e})"), st.just("L.pop()"), st.just("d['k'] = x"),
    st.just("x += 1"), st.just("board = init_board(8, 8)"), st.just("board = 5"), st.just("pass"),
)


def _block(body, depth):
    indent = "    " * depth
    return "\n".join(indent + line for line in body)


@st.composite
def statements(draw, depth=0):
    out = []
    for _ in range(draw(st.integers(1, 4))):
        kind = draw(st.integers(0, 5 if depth < 2 else 0))
        if kind <= 1:
            out.append(draw(simple_stmt))
        elif kind == 2:
            out.append(f"for i in range({draw(st.integers(0, 9))}):")
            out.append(_block(draw(statements(depth + 1)).split("\n"), 1))
        elif kind == 3:
            out.append(f"if {draw(expr)} > {draw(st.integers(-1, 5))}:")
            out.append(_block(draw(statements(depth + 1)).split("\n"), 1))
        elif kind == 4:
            out.append("while n < 5:")
            out.append(_block(["n = n + 1", *draw(statements(depth + 1)).split("\n")], 1))
        else:
            out.append("def f(x, color='red'):")
            out.append(_block([*draw(statements(depth + 1)).split("\n"), "return x"], 1))
    return "\n".join(out)


@SETTINGS
@given(statements())
def test_grammar_programs(body):
    program = "x = 1\nn = 0\nL = [1, 2]\nd = {}\ndef f(x):\n    return x\n" + body
    _assert_result(execute(program, limits=LIMITS))


@SETTINGS
@given(st.lists(st.tuples(st.sampled_from(SHAPES + ("bolt",)), st.sampled_from(COLORS + ("pink",)),
                          st.integers(-1, 8), st.integers(-1, 8)), max_size=12))
def test_put_only_programs_agree_with_the_world(puts):
    program = "\n".join(f"put(board, {s!r}, {c!r}, {x}, {y})" for s, c, x, y in puts)
    board, error = Board(8, 8), None
    for args in puts:
        try:
            put(board, *args)
        except WorldError as exc:
            error = exc.code
            break
    ex = execute(program, limits=LIMITS)
    assert (ex.ok, ex.error, ex.cells, ex.puts) == (error is None, error, board.cells(), board.puts)


# --- random syntax trees ---------------------------------------------------------------------------

names = st.sampled_from(["x", "board", "put", "range", "eval", "__class__", "_x", "open", "L", "ｅｖａｌ"])
leaf = st.one_of(
    st.integers(-3, 10**12).map(ast.Constant), st.sampled_from(["red", "washer", "{0.__class__}"]).map(ast.Constant),
    names.map(lambda n: ast.Name(n, ast.Load())),
)
binops = st.sampled_from([ast.Add(), ast.Sub(), ast.Mult(), ast.Pow(), ast.LShift(), ast.Mod(), ast.FloorDiv()])
attrs = st.sampled_from(["append", "format", "__class__", "gi_frame", "upper", "keys", "__globals__"])
exprs = st.recursive(leaf, lambda inner: st.one_of(
    st.builds(ast.BinOp, inner, binops, inner),
    st.builds(lambda f, a: ast.Call(f, a, []), inner, st.lists(inner, max_size=3)),
    st.builds(lambda v, a: ast.Attribute(v, a, ast.Load()), inner, attrs),
    st.builds(lambda e: ast.List(e, ast.Load()), st.lists(inner, max_size=3)),
    st.builds(lambda v, i: ast.Subscript(v, i, ast.Load()), inner, inner),
    st.builds(lambda b: ast.Lambda(ast.arguments([], [ast.arg("a")], None, [], [], None, []), b), inner),
    st.builds(lambda e: ast.JoinedStr([ast.FormattedValue(e, -1, None)]), inner),
    st.builds(lambda e: ast.GeneratorExp(e, [ast.comprehension(ast.Name("a", ast.Store()),
                                                               ast.Call(ast.Name("range", ast.Load()), [e], []), [], 0)]), inner),
), max_leaves=8)
stmts = st.one_of(
    exprs.map(ast.Expr),
    st.builds(lambda n, v: ast.Assign([ast.Name(n, ast.Store())], v), names, exprs),
    st.builds(lambda t, b: ast.While(t, [ast.Expr(b)], []), exprs, exprs),
    st.builds(lambda i, b: ast.For(ast.Name("x", ast.Store()), i, [ast.Expr(b)], []), exprs, exprs),
    st.builds(lambda n: ast.Import([ast.alias(n)]), st.sampled_from(["os", "sys"])),
    st.builds(lambda b: ast.FunctionDef("g", ast.arguments([], [], None, [], [], None, []), [ast.Return(b)], []), exprs),
    st.builds(lambda b: ast.Try([ast.Expr(b)], [ast.ExceptHandler(None, None, [ast.Pass()])], [], []), exprs),
)


@SETTINGS
@given(st.lists(stmts, min_size=1, max_size=5))
def test_random_syntax_trees(body):
    source = ast.unparse(ast.fix_missing_locations(ast.Module(body, [])))
    _assert_result(execute(source, limits=LIMITS))
