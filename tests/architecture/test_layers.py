"""The layers of docs/ARCHITECTURE.md, enforced: every import of a sartco module (top-level or
inside a function) in sartco/, games/ and tools/ points down or sideways within its own package,
never up, and no two packages import each other."""
from __future__ import annotations

import ast
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]

# lowest first; a module may import modules of its own rank's package and of lower ranks
LAYERS = [
    ("settings", ["sartco.settings"]),
    ("base", ["sartco.errors", "sartco.dataset", "sartco.episode", "sartco.text", "sartco.syntax", "sartco.clock",
              "sartco.collector"]),
    ("world", ["sartco.world"]),
    # sartco.program by side of the wall (docs/sandbox.md, "The sandbox's rooms"): the stand-ins a
    # program calls, the check that reads a program before it runs, the child that runs it, then the
    # contract (Limits, Execution) and the parent's side on top
    ("program stand-ins", ["sartco.program.standins"]),
    ("program check", ["sartco.program.check"]),
    ("program contract", ["sartco.program.execution"]),
    ("program child", ["sartco.program.child"]),
    ("program", ["sartco.program"]),
    ("data", ["sartco.instances", "sartco.follower"]),
    ("published", ["sartco.published"]),
    ("scores", ["sartco.scores"]),
    ("paper", ["sartco.paper"]),
    ("register", ["sartco.register"]),
    # sartco.clem: one package per thing it serves (sartco/clem/__init__.py); the games (sartco/games:
    # one package per game, all of its own code) share a rank, so neither imports the other
    ("clem core", ["sartco.clem.core"]),
    ("clem players", ["sartco.clem.players"]),
    ("games", ["sartco.games.instruct", "sartco.games.describe"]),
    ("clem tooling", ["sartco.clem.tooling"]),
    # the files clemcore loads by path (backends/<name>_api.py; `sartco register` copies them)
    ("clem backends", ["sartco.clem.backends"]),
    ("protocols", ["sartco.protocols"]),
    # rewards for RL trainers over our protocol's episodes (ids of sartco.protocols)
    ("reward", ["sartco.reward"]),
    ("top", ["sartco.report", "sartco.instancegen", "sartco.cli", "sartco.__main__", "sartco.bench_execute", "sartco.suite", "sartco.suite_worker", "sartco.schedule", "sartco.doctor", "games", "tools"]),
]
TOP = len(LAYERS) - 1  # the entry points may use each other (the `sartco` command dispatches to them)
RANK = {package: rank for rank, (_, packages) in enumerate(LAYERS) for package in packages}
CONTAINERS = ("sartco", "sartco.clem", "sartco.games")  # folders of packages: no layer of their own


def package_of(module: str) -> str:
    """The layer package a dotted module name belongs to (its longest listed prefix)."""
    parts = module.split(".")
    for n in range(len(parts), 0, -1):
        if ".".join(parts[:n]) in RANK:
            return ".".join(parts[:n])
    if module.removesuffix(".__init__") in CONTAINERS:
        return "sartco.__init__"  # the containers: their __init__ holds no code (test_containers_hold_no_code)
    raise AssertionError(f"module {module} belongs to no layer of tests/architecture/test_layers.py")


def modules(root: Path = ROOT, bases: tuple[str, ...] = ("sartco", "games", "tools")) -> list[tuple[str, Path]]:
    """(dotted name, file) of every module under `bases`; a package's __init__.py is `pkg.__init__`."""
    out = []
    for base in bases:
        for path in sorted((root / base).rglob("*.py")):
            out.append((".".join(path.relative_to(root).with_suffix("").parts), path))
    return out


def imports_of(module: str, path: Path, known: set[str], prefix: str = "sartco") -> list[tuple[int, str]]:
    """(line, imported module of `known`) of every import statement in the file, at any depth
    (inside functions, classes, `if` blocks too): `import a.b`, `from a import b`, `from . import
    b`, `from .a import b`. A name imported from a package is its submodule when there is one
    (`from . import named` is named.py, not the package), else the package's __init__. Only
    modules whose name starts with `prefix` count."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    parts = module.split(".")
    here = parts[:-1]  # the package a relative import starts from (a package's __init__: itself)

    def node_of(name: str) -> str:
        return name if name in known else f"{name}.__init__" if f"{name}.__init__" in known else ""

    out = []
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom):
            base = here[:len(here) - node.level + 1] if node.level else []
            package = ".".join(base + ([node.module] if node.module else []))
            for alias in node.names:
                out.append((node.lineno, node_of(f"{package}.{alias.name}") or node_of(package) or package))
        elif isinstance(node, ast.Import):
            out += [(node.lineno, node_of(alias.name) or alias.name) for alias in node.names]
    return [(line, name) for line, name in out if name == prefix or name.startswith(prefix + ".")]


def import_graph(root: Path = ROOT, bases: tuple[str, ...] = ("sartco", "games", "tools"),
                 prefix: str = "sartco") -> dict[str, dict[str, int]]:
    """module -> {imported module: line} over every import of every module."""
    found = modules(root, bases)
    known = {module for module, _ in found}
    return {module: {name: line for line, name in reversed(imports_of(module, path, known, prefix))
                     if name in known and name != module}
            for module, path in found}


def find_cycle(graph: dict[str, dict[str, int]]) -> list[str] | None:
    """One import cycle (modules, the first repeated at the end), or None. A package's __init__
    importing its own submodules and a submodule importing from its package's __init__ are both
    edges: either side of such a pair is a real cycle."""
    colour: dict[str, int] = {}
    stack: list[str] = []

    def visit(m: str) -> list[str] | None:
        colour[m] = 1
        stack.append(m)
        for t in sorted(graph.get(m, ())):
            if colour.get(t) == 1:
                return stack[stack.index(t):] + [t]
            if t not in colour and (found := visit(t)):
                return found
        stack.pop()
        colour[m] = 2
        return None

    for m in sorted(graph):
        if m not in colour and (cycle := visit(m)):
            return cycle
    return None


def edges() -> list[tuple[str, str, str]]:
    """(importing package, imported package, 'file:line') for every import between packages."""
    out = []
    paths = dict(modules())
    for module, targets in import_graph().items():
        mine = package_of(module)
        for name, line in targets.items():
            theirs = package_of(name)
            if theirs != mine and "sartco.__init__" not in (mine, theirs):
                out.append((mine, theirs, f"{paths[module].relative_to(ROOT)}:{line}"))
    return out


def test_every_module_has_a_layer():
    for module, _ in modules():
        package_of(module)


@pytest.mark.parametrize("container", ["sartco.clem", "sartco.games"])
def test_containers_hold_no_code(container):
    """sartco/clem and sartco/games are only their packages: the __init__ is a docstring, and
    `from sartco.clem import x` (a module by the container's name, which no layer would check)
    appears nowhere."""
    tree = ast.parse((ROOT / container.replace(".", "/") / "__init__.py").read_text(encoding="utf-8"))
    assert all(isinstance(node, ast.Expr) and isinstance(node.value, ast.Constant) for node in tree.body)
    bare = [f"{module}: line {line}" for module, targets in import_graph().items()
            for name, line in targets.items() if name == f"{container}.__init__"]
    assert not bare, f"imports of the container {container} (name the package):\n" + "\n".join(bare)


def test_imports_point_down():
    upward = [f"{where}: {mine} imports {theirs}" for mine, theirs, where in edges()
              if RANK[theirs] > RANK[mine] or (RANK[theirs] == RANK[mine] and RANK[mine] != TOP)]
    assert not upward, "imports against the layers of docs/ARCHITECTURE.md:\n" + "\n".join(upward)


def test_no_cycle_between_modules():
    cycle = find_cycle(import_graph())
    assert cycle is None, "import cycle: " + " -> ".join(cycle or [])


def _plant(root: Path, files: dict[str, str]) -> None:
    for name, text in files.items():
        (root / name).parent.mkdir(parents=True, exist_ok=True)
        (root / name).write_text(text, encoding="utf-8")


@pytest.mark.parametrize("closing", [
    "from . import a\n",                                   # the form the old check read as the package
    "def later():\n    from . import a\n    return a\n",   # inside a function
    "from .a import VALUE\n",
    "import plant.a\n",
    "from plant import a\n",
])
def test_a_planted_cycle_is_found(tmp_path, closing):
    """The checker run on a package written here: a imports b by `from . import b`, b imports a
    back in each import form; every one closes a cycle the check reports."""
    _plant(tmp_path, {"plant/__init__.py": "", "plant/a.py": "from . import b\nVALUE = 1\n", "plant/b.py": closing})
    cycle = find_cycle(import_graph(tmp_path, ("plant",), prefix="plant"))
    assert cycle is not None and set(cycle) == {"plant.a", "plant.b"}, cycle


def test_a_name_of_the_package_is_no_edge_to_a_module(tmp_path):
    """`from . import VALUE` (a name of the package's __init__, no module) is an edge to the
    __init__, not to some submodule: no cycle between a and b here."""
    _plant(tmp_path, {"plant/__init__.py": "VALUE = 1\n", "plant/a.py": "from . import b\n",
                      "plant/b.py": "from . import VALUE\n"})
    graph = import_graph(tmp_path, ("plant",), prefix="plant")
    assert graph["plant.b"] == {"plant.__init__": 1} and find_cycle(graph) is None


def test_largest_module_is_small():
    sizes = sorted(((len(p.read_text(encoding="utf-8").splitlines()), p.relative_to(ROOT)) for _, p in modules()),
                   reverse=True)
    big = [f"{p}: {n} lines" for n, p in sizes if n >= 300]
    assert not big, "modules of 300 lines or more:\n" + "\n".join(big)


def test_named_test_files_exist():
    """A test file the code or the docs name (`tests/.../test_x.py`) is there: none goes stale
    when tests move."""
    named = re.compile(r"\btests/[\w/]+\.py\b")
    texts = [path for _, path in modules()] + sorted((ROOT / "docs").glob("*.md")) + [ROOT / "README.md"]
    stale = [f"{path.relative_to(ROOT)}: {name}" for path in texts
             for name in sorted(set(named.findall(path.read_text(encoding="utf-8")))) if not (ROOT / name).is_file()]
    assert not stale, "test files named but missing:\n" + "\n".join(stale)


def documented_layers() -> list[tuple[str, list[str]]]:
    """(layer, packages) of the table in docs/ARCHITECTURE.md's "Layers", in its order: the second
    column's names in backticks (`games/*` and `tools/*` as the folders)."""
    text = (ROOT / "docs" / "ARCHITECTURE.md").read_text(encoding="utf-8")
    section = text[text.index("\n## Layers"):]
    section = section[:section.index("\n## ", 1)]
    rows = [row.split("|")[1:3] for row in section.splitlines() if row.startswith("| ") and "`" in row.split("|")[2]]
    return [(layer.strip(), [name.removesuffix("/*") for name in re.findall(r"`([^`]+)`", packages)])
            for layer, packages in rows]


def test_the_documented_layers_are_the_checked_ones():
    """docs/ARCHITECTURE.md's table names the layers this test enforces, in the same order, each with
    the same packages (sartco.__main__, `python -m sartco`, goes unnamed beside sartco.cli)."""
    checked = [(layer, [p for p in packages if p != "sartco.__main__"]) for layer, packages in LAYERS]
    assert documented_layers() == checked
