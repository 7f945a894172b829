"""Every shell command README.md and docs/*.md show is run here, or listed in LONG with the reason
it is not, so that no documented command goes stale.

The rule (README, "The docs"):
- A command is a line of a fenced block tagged `sh`; a line ending in `\\` goes on with the next,
  `#` starts a comment, blank and comment-only lines are no command.
- Every fenced block carries a tag of TAGS (`text` for output and layouts, `json`, `python`), so
  no command hides in an untagged block; commands in prose (in backticks) are references or
  synopses with placeholders, not run.
- Each `sh` block runs command by command, in order, in a fresh copy of the checkout's files
  (git's tracked and untracked-but-not-ignored ones) with `../shared` beside it, this venv's bin/
  first on PATH and the copy first on PYTHONPATH, so sartco's paths are the copy's and this
  checkout is never written. A `cd` carries over to the block's next command. Each command must
  exit 0 within TIMEOUT; after the block, every file of the copy that the checkout has must be
  byte-identical to it (a documented command leaves the committed files as they are, and
  rewrites the generated ones byte for byte).
- A command of LONG (its exact text -> why) is not run: over a minute here, or it needs a model
  server, an API key or a wheel install, or the output of a command that is not run. Every LONG
  entry must still be a command of some doc.
A command that fails here either breaks the docs or belongs in LONG, with its reason.
- A block that plays the README's own model (`-m my-model`) runs against a stub server that answers
  with the gold code (own_model): the README's key.json and model registry entry are written as
  shown, with the stub's address; the registry is restored before the comparison.

Relative links of the same files must reach a file, and a `#fragment` a heading of that file.
"""
from __future__ import annotations

import contextlib
import hashlib
import json
import os
import re
import shutil
import subprocess
import sys
import time
from pathlib import Path

import pytest

from sartco import settings
from sartco.clem.tooling.stub_server import StubServer, answer_table

REPO = Path(__file__).resolve().parents[2]
DOCS = [REPO / "README.md", *sorted((REPO / "docs").glob("*.md"))]
TAGS = {"sh", "text", "json", "python"}
# a minute on an idle machine; the margin is for `make test`'s load on two cores
TIMEOUT = 180

LONG = {
    "make install": "creates .venv and installs the project with pip: minutes",
    "sartco suite -r results-mine --out scores-mine -m my-model --erring -g cobot_instruct -l 512":
        "needs your model's server; 650 episodes (its smoke run above is played against a stub server here)",
    "clem run -g cobot_instruct_paper -m <model> -t 0 -l 250": "needs your model; 1,950 episodes",
    "clem score; sartco report -r results": "scores the paper protocol's run above, which is not run here",
    # docs/models.md, "Installed anywhere": the same steps in a wheel install, 5-7 min
    "mkdir work && cd work": "a wheel install without a checkout: tests/packaging/test_wheel.py runs these steps",
    "sartco games ../sartco-games": "a wheel install: tests/packaging/test_wheel.py",
    "sartco generate --seed 42 --out instances/v1": "a wheel install (the package's v1 config): tests/packaging/test_wheel.py",
    "python ../sartco-games/cobot_instruct/instancegenerator.py --dataset instances/v1":
        "a wheel install: tests/packaging/test_wheel.py",
    "python ../sartco-games/cobot_describe/instancegenerator.py --dataset instances/v1 --slice 1":
        "a wheel install: tests/packaging/test_wheel.py",
    "clem run -g cobot_instruct -m rulebased -i instances_smoke -r results": "a wheel install: tests/packaging/test_wheel.py",
    "clem run -g cobot_describe -m mock -i instances_slice -r results": "a wheel install: tests/packaging/test_wheel.py",
    "clem score -r results && clem transcribe -r results && sartco report -r results --out scores":
        "a wheel install: tests/packaging/test_wheel.py",
}


def fences(text: str) -> list[tuple[int, str, list[tuple[int, str]]]]:
    """(line of the opening fence, tag, [(line, text) of the body]) of every fenced block."""
    out: list[tuple[int, str, list[tuple[int, str]]]] = []
    block: tuple[int, str, list[tuple[int, str]]] | None = None
    for number, line in enumerate(text.splitlines(), 1):
        if line.startswith("```"):
            if block is None:
                block = (number, line[3:].strip(), [])
            else:
                out.append(block)
                block = None
        elif block is not None:
            block[2].append((number, line))
    assert block is None, f"a fence opened on line {block[0]} is never closed"
    return out


def commands(body: list[tuple[int, str]]) -> list[tuple[int, str]]:
    """(line, command) of an `sh` block's body, by the rule of the module's doc."""
    out: list[tuple[int, str]] = []
    pending: tuple[int, str] | None = None
    for number, line in body:
        if pending is not None:
            number, line = pending[0], pending[1] + " " + line.strip()
            pending = None
        if line.rstrip().endswith("\\"):
            pending = (number, line.rstrip()[:-1].rstrip())
            continue
        command = re.sub(r"(^|\s)#.*$", "", line).strip()
        if command:
            out.append((number, " ".join(command.split())))
    assert pending is None, f"line {pending[0]}: a continued command ends the block"
    return out


def sh_blocks() -> list[tuple[str, list[tuple[int, str]]]]:
    """(`file:line`, commands) of every `sh` block of the docs."""
    return [(f"{doc.relative_to(REPO)}:{start}", commands(body))
            for doc in DOCS for start, tag, body in fences(doc.read_text(encoding="utf-8")) if tag == "sh"]


BLOCKS = sh_blocks()


def test_every_fence_has_a_known_tag():
    untagged = [f"{doc.relative_to(REPO)}:{start}: ```{tag}" for doc in DOCS
                for start, tag, _ in fences(doc.read_text(encoding="utf-8")) if tag not in TAGS]
    assert not untagged, (f"fenced blocks need one of the tags {sorted(TAGS)} (`sh` for commands, which "
                          "tests/docs/test_doc_commands.py runs):\n" + "\n".join(untagged))


def test_the_rule_reads_commands_comments_and_continued_lines():
    text = ("```sh\n# a comment line\nclem run -g cobot_instruct \\\n  -m mock   # played\n\n"
            "sartco report -r results#1\n```\n```text\nnot a command\n```\n")
    (start, tag, body), (_, other, _) = fences(text)
    assert (start, tag, other) == (1, "sh", "text")
    assert commands(body) == [(3, "clem run -g cobot_instruct -m mock"), (6, "sartco report -r results#1")]


def test_every_long_entry_is_a_documented_command():
    shown = {command for _, block in BLOCKS for _, command in block}
    stale = sorted(set(LONG) - shown)
    assert not stale, "LONG lists commands no doc shows any more (remove them):\n" + "\n".join(stale)
    assert all(reason.strip() for reason in LONG.values())


def checkout_files() -> list[str]:
    listed = subprocess.run(["git", "ls-files", "-z", "--cached", "--others", "--exclude-standard"], cwd=REPO,
                            capture_output=True, check=True).stdout.decode().split("\0")
    return [name for name in listed if name and (REPO / name).is_file()]


def digest(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


OWN_MODEL = "-m my-model"


def own_model(copy: Path, base_url: str) -> None:
    """The README's key.json and model registry entry in the copy, the server at `base_url`."""
    blocks = [json.loads("\n".join(line for _, line in body))
              for _, tag, body in fences((REPO / "README.md").read_text(encoding="utf-8")) if tag == "json"]
    key = next(b for b in blocks if isinstance(b, dict) and "openai_compatible" in b)
    entries = next(b for b in blocks if isinstance(b, list) and b[0].get("model_name") == "my-model")
    key["openai_compatible"]["base_url"] = base_url
    (copy / "key.json").write_text(json.dumps(key))
    registry = json.loads((copy / "model_registry.json").read_text())
    (copy / "model_registry.json").write_text(json.dumps(registry + entries))


@pytest.mark.slow  # clem runs end to end: tests/conftest.py starts this file early
@pytest.mark.parametrize("where, block", [b for b in BLOCKS if any(c not in LONG for _, c in b[1])],
                         ids=[w for w, b in BLOCKS if any(c not in LONG for _, c in b)])
def test_documented_commands_run(tmp_path, where, block):
    files = checkout_files()
    copy = tmp_path / "repo"
    for name in files:
        (copy / name).parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(REPO / name, copy / name)
    if settings.DATA is not None and settings.DATA.is_dir():  # ../shared/sartco-data, as the docs name it
        (tmp_path / "shared").mkdir()
        (tmp_path / "shared" / "sartco-data").symlink_to(settings.DATA)
    env = {k: v for k, v in os.environ.items() if k not in ("CLEMBENCH_HOME", "SARTCO_DATA", "SARTCO_RESOURCES")}
    env["PATH"] = f"{Path(sys.executable).parent}{os.pathsep}{env.get('PATH', '')}"
    env["PYTHONPATH"] = str(copy)
    marker, took = tmp_path / "cwd", []
    with contextlib.ExitStack() as stack:
        if any(OWN_MODEL in c and c not in LONG for _, c in block):
            smoke = json.loads((REPO / "games" / "cobot_instruct" / "in" / "instances_smoke.json").read_text())
            server = stack.enter_context(StubServer(answer_table(
                [i for e in smoke["experiments"] for i in e["game_instances"]]), latency=0.0))
            own_model(copy, server.base_url)
        run_block(where, block, copy, env, marker, took)
    shutil.copy2(REPO / "model_registry.json", copy / "model_registry.json")
    changed = [name for name in files if not (copy / name).is_file() or digest(copy / name) != digest(REPO / name)]
    assert not changed, f"{where}: the commands changed or removed files of the checkout:\n" + "\n".join(changed)
    print("\n".join(took))


def run_block(where: str, block, cwd: Path, env: dict, marker: Path, took: list) -> None:
    """Each command of the block in order (a `cd` carries over); must exit 0 within TIMEOUT."""
    for line, command in block:
        if command in LONG:
            continue
        script = f"{command}\n__status=$?\npwd > '{marker}'\nexit $__status\n"
        start = time.monotonic()
        try:
            done = subprocess.run(["bash", "-c", script], cwd=cwd, env=env, capture_output=True, text=True,
                                  timeout=TIMEOUT)
        except subprocess.TimeoutExpired:
            pytest.fail(f"{where}, line {line}: `{command}` ran over {TIMEOUT} s: "
                        "add it to LONG in tests/docs/test_doc_commands.py with a reason, or show a shorter one")
        took.append(f"{time.monotonic() - start:5.1f} s  {command}")
        assert done.returncode == 0, (
            f"{where}, line {line}: `{command}` exited {done.returncode}; fix the doc, or add it to LONG in "
            f"tests/docs/test_doc_commands.py with a reason\n{done.stdout[-1500:]}\n{done.stderr[-1500:]}")
        cwd = Path(marker.read_text().strip())


def slug(heading: str) -> str:
    """GitHub's anchor of a heading: lower case, punctuation but `-` and `_` dropped, spaces as `-`."""
    return re.sub(r"[^\w\- ]", "", heading.strip().lower()).replace(" ", "-")


def test_relative_links_reach_their_file_and_heading():
    broken = []
    for doc in DOCS:
        text = doc.read_text(encoding="utf-8")
        for target in re.findall(r"\]\(([^)\s]+)\)", text):
            if re.match(r"[a-z]+:", target):
                continue
            name, _, fragment = target.partition("#")
            path = (doc.parent / name).resolve() if name else doc
            if not path.exists():
                broken.append(f"{doc.relative_to(REPO)}: {target} (no such file)")
            elif fragment and path.suffix == ".md":
                headings = {slug(h) for h in re.findall(r"^#+ (.+)$", path.read_text(encoding="utf-8"), re.M)}
                if fragment not in headings:
                    broken.append(f"{doc.relative_to(REPO)}: {target} (no such heading)")
    assert not broken, "links that lead nowhere:\n" + "\n".join(broken)


def test_the_readme_stays_short():
    """A newcomer reads it to the end (issue 35): what the project is, the two commands, a first
    run, the layout and a map of the docs; the rest has its page in docs/."""
    lines = len((REPO / "README.md").read_text(encoding="utf-8").splitlines())
    assert lines <= 250, f"README.md has {lines} lines: move a concern's text into its page of docs/"
