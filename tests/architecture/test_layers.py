"""The layers of docs/ARCHITECTURE.md, enforced: every import of a sartco module (top-level or
inside a function) in sartco/, games/ and tools/ points down or sideways within its own package,
never up, and no two packages import each other."""
from __future__ import annotations

import ast
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]

# lowest first; a module may import modules of its own rank's package and of lower ranks
LAYERS = [
    ("settings", ["sartco.settings"]),
    ("base", ["sartco.errors", "sartco.dataset", "sartco.episode", "sartco.text"]),
    ("world", ["sartco.world"]),
    ("program", ["sartco.program"]),
    ("data", ["sartco.instances", "sartco.follower"]),
    ("published", ["sartco.published"]),
    ("scores", ["sartco.scores"]),
    ("paper", ["sartco.paper"]),
    ("register", ["sartco.register"]),
    # sartco.clem: one package per thing it serves (sartco/clem/__init__.py); the games' own logic
    # packages share a rank, so none of them imports another
    ("clem core", ["sartco.clem.core"]),
    ("clem players", ["sartco.clem.players"]),
    ("clem games", ["sartco.clem.instruct", "sartco.clem.describe", "sartco.clem.paper"]),
    ("clem tooling", ["sartco.clem.tooling"]),
    # the files clemcore loads by path (backends/<name>_api.py; `sartco register` copies them)
    ("clem backends", ["sartco.clem.backends"]),
    ("protocols", ["sartco.protocols"]),
    # rewards for RL trainers over our protocol's episodes (ids of sartco.protocols)
    ("reward", ["sartco.reward"]),
    ("top", ["sartco.report", "sartco.instancegen", "sartco.cli", "sartco.__main__", "sartco.bench_execute", "games", "tools"]),
]
TOP = len(LAYERS) - 1  # the entry points may use each other (the `sartco` command dispatches to them)
RANK = {package: rank for rank, (_, packages) in enumerate(LAYERS) for package in packages}


def package_of(module: str) -> str:
    """The layer package a dotted module name belongs to (its longest listed prefix)."""
    parts = module.split(".")
    for n in range(len(parts), 0, -1):
        if ".".join(parts[:n]) in RANK:
            return ".".join(parts[:n])
    if module in ("sartco", "sartco.__init__", "sartco.clem", "sartco.clem.__init__"):
        return "sartco.__init__"  # the containers: their __init__ holds no code (test_containers_hold_no_code)
    raise AssertionError(f"module {module} belongs to no layer of tests/architecture/test_layers.py")


def modules() -> list[tuple[str, Path]]:
    out = []
    for base in ("sartco", "games", "tools"):
        for path in sorted((ROOT / base).rglob("*.py")):
            out.append((".".join(path.relative_to(ROOT).with_suffix("").parts), path))
    return out


def imports_of(module: str, path: Path) -> list[tuple[int, str]]:
    """(line, imported sartco module) of every import statement in the file."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    here = module.split(".") if path.name == "__init__.py" else module.split(".")[:-1]
    out = []
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom):
            if node.level:
                base = here[:len(here) - node.level + 1]
                name = ".".join(base + ([node.module] if node.module else []))
            else:
                name = node.module or ""
            out.append((node.lineno, name))
        elif isinstance(node, ast.Import):
            out += [(node.lineno, alias.name) for alias in node.names]
    return [(line, name) for line, name in out if name == "sartco" or name.startswith("sartco.")]


def edges() -> list[tuple[str, str, str]]:
    """(importing package, imported package, 'file:line') for every import between packages."""
    out = []
    for module, path in modules():
        mine = package_of(module)
        for line, name in imports_of(module, path):
            theirs = package_of(name)
            if theirs != mine and "sartco.__init__" not in (mine, theirs):
                out.append((mine, theirs, f"{path.relative_to(ROOT)}:{line}"))
    return out


def test_every_module_has_a_layer():
    for module, _ in modules():
        package_of(module)


def test_containers_hold_no_code():
    """sartco/clem is only its packages: its __init__ is a docstring, and `from sartco.clem import x`
    (a module by the container's name, which no layer would check) appears nowhere."""
    tree = ast.parse((ROOT / "sartco/clem/__init__.py").read_text(encoding="utf-8"))
    assert all(isinstance(node, ast.Expr) and isinstance(node.value, ast.Constant) for node in tree.body)
    bare = [f"{path.relative_to(ROOT)}:{line}" for module, path in modules()
            for line, name in imports_of(module, path) if name == "sartco.clem"]
    assert not bare, "imports of the container sartco.clem (name the package):\n" + "\n".join(bare)


def test_imports_point_down():
    upward = [f"{where}: {mine} imports {theirs}" for mine, theirs, where in edges()
              if RANK[theirs] > RANK[mine] or (RANK[theirs] == RANK[mine] and RANK[mine] != TOP)]
    assert not upward, "imports against the layers of docs/ARCHITECTURE.md:\n" + "\n".join(upward)


def test_no_cycle_between_modules():
    graph: dict[str, set[str]] = {}
    for module, path in modules():
        targets = set()
        for _, name in imports_of(module, path):
            # `from sartco.x import y` may name a module y or a member of x: take the module
            targets.add(name)
        graph[module] = targets
    known = set(graph)

    def resolve(name: str) -> str | None:
        while name and name not in known:
            name = name.rpartition(".")[0]
        return name or None

    adj = {m: {r for t in ts if (r := resolve(t)) and r != m and not m.startswith(r + ".")} for m, ts in graph.items()}
    # a package's __init__ importing its own submodules is not a cycle with them
    adj = {m: {t for t in ts if not (m.endswith("__init__") or t + ".__init__" == m)} for m, ts in adj.items()}
    colour: dict[str, int] = {}
    stack: list[str] = []

    def visit(m: str) -> list[str] | None:
        colour[m] = 1
        stack.append(m)
        for t in sorted(adj.get(m, ())):
            if colour.get(t) == 1:
                return stack[stack.index(t):] + [t]
            if t not in colour and (found := visit(t)):
                return found
        stack.pop()
        colour[m] = 2
        return None

    for m in sorted(adj):
        if m not in colour and (cycle := visit(m)):
            pytest.fail("import cycle: " + " -> ".join(cycle))


def test_largest_module_is_small():
    sizes = sorted(((len(p.read_text(encoding="utf-8").splitlines()), p.relative_to(ROOT)) for _, p in modules()),
                   reverse=True)
    big = [f"{p}: {n} lines" for n, p in sizes if n >= 300]
    assert not big, "modules of 300 lines or more:\n" + "\n".join(big)
