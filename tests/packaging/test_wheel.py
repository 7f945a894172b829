"""Installable anywhere (issue 25): the wheel, installed (not editable) into a fresh venv in a
temporary folder, used from a folder that is not the checkout (PYTHONPATH unset), generates a
dataset and the instances of both games, plays a smoke run of cobot_instruct and cobot_describe
with mock and rulebased through a game_registry.json there, and scores, transcribes and reports.

The venv holds the wheel and exactly the distributions its requirements resolve to, linked from
this interpreter's environment (`installed`): `pip check` there proves every declared requirement
met, the commands prove nothing undeclared is needed. Slow: building the wheel (about 10 s), then
each command in the venv imports clemcore anew (about 1 s, forked from a warm parent:
tests/helpers/forkserver.py)."""
from __future__ import annotations

import email.parser
import json
import os
import shutil
import subprocess
import sys
import zipfile
from importlib import metadata
from pathlib import Path

import pytest
from forkserver import command
from packaging.requirements import Requirement
from packaging.utils import canonicalize_name

pytestmark = pytest.mark.slow
REPO = Path(__file__).resolve().parents[2]


def run(*args, cwd: Path, env: dict, timeout: int = 900) -> subprocess.CompletedProcess:
    """The command as a process of its own; the venv's Python programs are forked from a server
    that the venv's python started (tests/helpers/forkserver.py), which imports nothing of the checkout."""
    done = command(args, cwd=cwd, env=env, timeout=timeout)
    assert done.returncode == 0, f"{' '.join(map(str, args))} failed:\n{done.stdout[-2000:]}\n{done.stderr[-3000:]}"
    return done


def source_copy(folder: Path) -> Path:
    """What the wheel is built from, copied out of the checkout: setuptools writes build/ and
    *.egg-info beside the sources, which must not change under the tests running beside this one."""
    from sartco.settings import GAME_FILES, GAME_NAMES  # the one list of what ships (setup.py)
    folder.mkdir()
    for name in ("pyproject.toml", "setup.py", "MANIFEST.in", "README.md"):
        shutil.copy(REPO / name, folder / name)
    for name in ("sartco", "resources"):
        shutil.copytree(REPO / name, folder / name, ignore=shutil.ignore_patterns("__pycache__", "*.pyc"))
    for game in GAME_NAMES:
        (folder / "games" / game).mkdir(parents=True)
        for name in GAME_FILES:
            shutil.copy(REPO / "games" / game / name, folder / "games" / game / name)
    return folder


def requirements_of(wheel: Path) -> list[str]:
    """The Requires-Dist lines of the wheel's METADATA."""
    with zipfile.ZipFile(wheel) as archive:
        [name] = [n for n in archive.namelist() if n.endswith(".dist-info/METADATA")]
        return email.parser.Parser().parsestr(archive.read(name).decode()).get_all("Requires-Dist") or []


def closure(requires: list[str]) -> list[metadata.Distribution]:
    """The installed distributions that `requires` needs, then theirs (markers and extras evaluated as
    pip does), from this interpreter's environment: what `pip install` of the wheel resolves to under
    constraints.txt (`make install` resolved the same requirements). Fails naming a missing or
    mismatched one."""
    found: dict[str, tuple[metadata.Distribution, set[str]]] = {}
    todo = [(Requirement(r), frozenset({""})) for r in requires]
    while todo:
        req, extras = todo.pop()
        if req.marker and not any(req.marker.evaluate({"extra": e}) for e in extras):
            continue
        name = canonicalize_name(req.name)
        try:
            dist = metadata.distribution(req.name)
        except metadata.PackageNotFoundError:
            pytest.fail(f"{req}: not installed here, so the wheel's dependencies cannot be linked")
        assert req.specifier.contains(dist.version, prereleases=True), f"{req}: {dist.version} installed"
        done = found[name][1] if name in found else set()
        wanted = {""} | set(req.extras)
        if name in found and wanted <= done:
            continue
        found[name] = (dist, done | wanted)
        todo += [(Requirement(r), frozenset(done | wanted)) for r in dist.requires or []]
    return [dist for dist, _ in found.values()]


def link_into(site: Path, bin_dir: Path, dists: list[metadata.Distribution]) -> None:
    """Each distribution's files (its RECORD) hard-linked into the venv's site-packages (copied where
    no link can be made), its console scripts written for the venv's python: the same files `pip
    install` would unpack, without unpacking and compiling them again."""
    for dist in dists:
        base = Path(dist.locate_file(""))
        assert dist.files, f"{dist.metadata['Name']}: installed without a RECORD of its files, cannot be linked"
        for entry in dist.files:
            rel = Path(os.path.normpath(entry))
            source = base / rel
            if rel.parts[0] == ".." or not source.is_file():  # bin/ scripts: written below
                continue
            (site / rel).parent.mkdir(parents=True, exist_ok=True)
            try:
                os.link(source, site / rel)
            except OSError:
                shutil.copy2(source, site / rel)
        for ep in dist.entry_points.select(group="console_scripts"):
            script = bin_dir / ep.name
            script.write_text(f"#!{bin_dir / 'python'}\nimport sys\nfrom {ep.module} import {ep.attr.split('.')[0]}\n"
                              f"sys.exit({ep.attr}())\n")
            script.chmod(0o755)


@pytest.fixture(scope="module")
def installed(tmp_path_factory):
    """(bin folder of a fresh venv holding the wheel, an environment that knows nothing of the checkout).
    The venv (no --system-site-packages) gets exactly the installed distributions the wheel's
    requirements resolve to (`closure`, hard-linked: resolving, downloading, unpacking and compiling
    them again took 32 s wall on an idle machine, 313 s on a loaded one), then the wheel with `pip
    install --no-deps`, and `pip check` proves every requirement in it satisfied; anything the code
    imports without declaring it is missing there, as in a user's venv. The venv gets no pip of its
    own: this interpreter's pip installs into it."""
    root = tmp_path_factory.mktemp("wheel")
    env = {k: v for k, v in os.environ.items()
           if k not in ("PYTHONPATH", "VIRTUAL_ENV", "SARTCO_DATA", "SARTCO_RESOURCES", "CLEMBENCH_HOME")}
    source = source_copy(root / "source")
    run(sys.executable, "-m", "pip", "wheel", "-q", "--no-deps", "-w", root / "dist", source, cwd=root, env=env)
    wheels = sorted((root / "dist").glob("sartco_bench-*.whl"))
    assert len(wheels) == 1
    run(sys.executable, "-m", "venv", "--without-pip", root / "venv", cwd=root, env=env)  # no --system-site-packages
    bin_dir = root / "venv" / "bin"
    site = Path(run(bin_dir / "python", "-c", "import sysconfig; print(sysconfig.get_path('purelib'))",
                    cwd=root, env=env).stdout.strip())
    dists = closure(requirements_of(wheels[0]))
    assert {canonicalize_name(d.metadata["Name"]) for d in dists} >= {"clemcore", "codebleu", "pyseccomp"}
    link_into(site, bin_dir, dists)
    run(sys.executable, "-m", "pip", "--python", bin_dir / "python", "install", "-q", "--no-deps", wheels[0],
        cwd=root, env=env)
    check = run(sys.executable, "-m", "pip", "--python", bin_dir / "python", "check", cwd=root, env=env)
    assert "No broken requirements found." in check.stdout
    env["PATH"] = f"{bin_dir}{os.pathsep}{env.get('PATH', '')}"
    return bin_dir, env


def test_the_wheel_plays_both_games_outside_the_checkout(installed, tmp_path):
    bin_dir, env = installed
    work, games = tmp_path / "work", tmp_path / "sartco-games"
    work.mkdir()

    where = run(bin_dir / "python", "-c", "import sartco, sartco.settings as s; print(sartco.__file__, s.CHECKOUT)",
                cwd=work, env=env).stdout.split()
    assert Path(where[0]).is_relative_to(bin_dir.parent) and where[1] == "None"  # the wheel's copy, no checkout

    run("sartco", "games", games, cwd=work, env=env)
    run("sartco", "register", cwd=work, env=env)
    registry = json.loads((work / "game_registry.json").read_text())
    assert {e["game_name"]: e["game_path"] for e in registry}["cobot_describe"] == str(games / "cobot_describe")
    assert [e["model_name"] for e in json.loads((work / "model_registry.json").read_text())] == ["rulebased", "erring"]

    run("sartco", "generate", "--seed", "42", "--out", "instances/v1", cwd=work, env=env)
    for name in (REPO / "instances" / "v1").iterdir():  # the packaged resources give the checkout's dataset
        assert (work / "instances" / "v1" / name.name).read_bytes() == name.read_bytes(), name.name
    dataset = work / "instances" / "v1"
    run("python", games / "cobot_instruct" / "instancegenerator.py", "--dataset", dataset, "--smoke", "1",
        "--ablation-episodes", "1", cwd=work, env=env)
    run("python", games / "cobot_describe" / "instancegenerator.py", "--dataset", dataset, "--slice", "1",
        cwd=work, env=env)
    smoke = json.loads((games / "cobot_instruct" / "in" / "instances_smoke.json").read_text())
    ours = json.loads((REPO / "games" / "cobot_instruct" / "in" / "instances_smoke.json").read_text())
    assert [e["game_instances"] for e in smoke["experiments"]] == \
        [e["game_instances"][:1] for e in ours["experiments"]]  # the same episodes as the checkout's

    assert "cobot_describe_dialogue" in run("clem", "list", "games", cwd=work, env=env).stdout
    for model in ("mock", "rulebased"):
        run("clem", "run", "-g", "cobot_instruct", "-m", model, "-i", "instances_smoke", "-r", "results",
            cwd=work, env=env)
        run("clem", "run", "-g", "cobot_describe", "-m", model, "-i", "instances_slice", "-r", "results",
            cwd=work, env=env)
    run("clem", "score", "-r", "results", cwd=work, env=env)
    run("clem", "transcribe", "-r", "results", cwd=work, env=env)
    report = run("sartco", "report", "-r", "results", "--out", "scores", cwd=work, env=env)
    assert "16 episodes" in report.stdout

    scores = {}
    for path in sorted((work / "results").rglob("scores.json")):
        model, game = path.relative_to(work / "results").parts[:2]
        scores.setdefault((model, game), []).append(json.loads(path.read_text())["episode scores"]["Main Score"])
    assert sorted(scores) == [("mock", "cobot_describe"), ("mock", "cobot_instruct"),
                              ("rulebased", "cobot_describe"), ("rulebased", "cobot_instruct")]
    assert scores[("mock", "cobot_instruct")] == [100.0] * 5 == scores[("rulebased", "cobot_instruct")]
    assert scores[("mock", "cobot_describe")] == [100.0] * 3 == scores[("rulebased", "cobot_describe")]
    assert len(list((work / "results").rglob("transcript.html"))) == 16
    assert (work / "scores" / "table3.md").is_file() and (work / "scores" / "report.html").is_file()


def test_the_wheel_without_a_data_folder_says_which_setting(installed, tmp_path):
    bin_dir, env = installed
    done = subprocess.run(["sartco", "export-prompts", "--protocol", "paper"], cwd=tmp_path, env=env,
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 2 and len(done.stderr.strip().splitlines()) == 1
    assert "SARTCO_DATA" in done.stderr and "--data" in done.stderr
