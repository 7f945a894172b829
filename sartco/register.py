"""`sartco register` and `sartco games`: make clemcore find sartco's models, backends and games in a
folder of the user's, by writing ordinary clemcore files there (nothing patches clemcore).

clemcore 3.7 reads `model_registry.json` and `<backend>_api.py` files only from the working directory
and from its own package, and games from `game_registry.json` and the folders below the working
directory. So, for the folder DIR you run `clem` in:

    sartco register [DIR]   (default: the working directory)
      DIR/model_registry.json  sartco's model entries (rulebased, erring: sartco/clem/backends/
                               model_registry.json) appended to the list already there; an entry of
                               the same model_name stays as the user wrote it (said on stderr), no
                               entry is reordered; a second run changes nothing
      DIR/<name>_api.py        one small file per sartco backend (rulebased, openai_batching) that
                               imports the backend's class from the installed package
    sartco games GAMES_DIR  (run it in the folder you run clem in)
      GAMES_DIR/<game>/        the game folders' files (clemgame.json, master.py, instancegenerator.py,
                               README.md) of cobot_instruct and cobot_describe, so that instances can be
                               generated into GAMES_DIR/<game>/in (never into site-packages); an existing
                               file that differs is left alone (said on stderr)
      ./game_registry.json     one entry per game entry of the clemgame.json files, with its game_path,
                               merged as model_registry.json is (by game_name). clem also finds every
                               game folder below the working directory by itself, so a GAMES_DIR there
                               would list each game twice (`clem run -g all` would play it twice): it is
                               refused; put the games beside it (e.g. ../sartco-games)

The checkout commits the result of `sartco register .` at its top (model_registry.json,
rulebased_api.py, openai_batching_api.py), so that `make main`, `make test` and the scripts find
them; tests/games/instruct/test_outside_repo.py checks that registering the checkout again changes nothing.
"""
from __future__ import annotations

import json
import sys
from pathlib import Path

from sartco.errors import UserError
from sartco.settings import BACKENDS, GAME_FILES, GAME_NAMES, GAMES

MODELS_FILE, GAMES_FILE = "model_registry.json", "game_registry.json"
HEADER = "# written by `sartco register`: clemcore loads this file by its path; the backend is in the sartco package\n"


def configure(parser) -> None:
    parser.add_argument("dir", nargs="?", type=Path, default=Path("."),
                        help="the folder you run clem in (default: the working directory)")
    parser.add_argument("-q", "--quiet", action="store_true", help="print nothing when nothing changed")


def configure_games(parser) -> None:
    parser.add_argument("dir", type=Path, help="where the game folders go (outside the working directory)")
    parser.add_argument("-q", "--quiet", action="store_true", help="print nothing when nothing changed")


def read_list(path: Path) -> list:
    """A registry file's entries ([] when there is none); a UserError naming the file when it is not
    a JSON list of objects."""
    if not path.exists():
        return []
    try:
        entries = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, json.JSONDecodeError) as exc:
        raise UserError(f"{path}: cannot read it as JSON ({exc}); fix or move it, nothing was written") from None
    if not isinstance(entries, list) or not all(isinstance(e, dict) for e in entries):
        raise UserError(f"{path}: expected a JSON list of entries (objects); fix or move it, nothing was written")
    return entries


def merge(path: Path, ours: list[dict], key: str) -> tuple[list[str], list[str]]:
    """Append to the registry file at `path` those of `ours` whose `key` it does not hold yet (the file's
    own entries first, unchanged and in their order). (names added, names kept as the user wrote them)."""
    entries = read_list(path)
    present = {e.get(key): e for e in entries}
    added = [e for e in ours if e[key] not in present]
    kept = [e[key] for e in ours if e[key] in present and present[e[key]] != e]
    if added:
        path.write_text(json.dumps(entries + added, indent=2) + "\n", encoding="utf-8")
    return [e[key] for e in added], kept


def backend_files() -> dict[str, str]:
    """file name -> the text `sartco register` writes, for every sartco backend."""
    return {p.name: HEADER + p.read_text(encoding="utf-8") for p in sorted(BACKENDS.glob("*_api.py"))}


def model_entries() -> list[dict]:
    return json.loads((BACKENDS / MODELS_FILE).read_text(encoding="utf-8"))


def write_new(path: Path, text: str, command: str, lines: list[str]) -> None:
    """Write a file that is not there; an equal file stays; another one too, said on stderr."""
    if not path.exists():
        path.write_text(text, encoding="utf-8")
        lines.append(f"{path}: written")
    elif path.read_text(encoding="utf-8") != text:
        print(f"sartco {command}: {path} exists and differs: kept (delete it to take this version's)",
              file=sys.stderr)


def merge_into(path: Path, ours: list[dict], key: str, command: str, lines: list[str]) -> None:
    """merge(), said: the names added on stdout (lines), the user's entries kept on stderr."""
    added, kept = merge(path, ours, key)
    if added:
        lines.append(f"{path}: added {', '.join(added)}")
    for name in kept:
        print(f"sartco {command}: {path} has its own entry '{name}': kept", file=sys.stderr)


def register(folder: Path) -> list[str]:
    """Register sartco's backends and models in `folder`; the lines saying what changed."""
    folder = _folder(folder)
    read_list(folder / MODELS_FILE)  # a malformed file stops everything before anything is written
    lines = write_backends(folder)
    merge_into(folder / MODELS_FILE, model_entries(), "model_name", "register", lines)
    return lines


def write_backends(folder: Path) -> list[str]:
    """sartco's <name>_api.py files in `folder` (a file there that differs is kept)."""
    lines: list[str] = []
    for name, text in backend_files().items():
        write_new(folder / name, text, "register", lines)
    return lines


def install_games(games_dir: Path, registry_dir: Path) -> list[str]:
    """Copy the games' files to games_dir/<game>/ and register them in registry_dir/game_registry.json."""
    registry_dir, games_dir = _folder(registry_dir).resolve(), Path(games_dir).resolve()
    if games_dir.is_relative_to(registry_dir):
        raise UserError(f"{games_dir}: inside {registry_dir}, where clem finds the games by itself and would list "
                        f"each twice beside {GAMES_FILE}; give a folder outside it (e.g. ../sartco-games)")
    read_list(registry_dir / GAMES_FILE)
    lines: list[str] = []
    entries = []
    for game in GAME_NAMES:
        source, target = GAMES / game, games_dir / game
        (target / "in").mkdir(parents=True, exist_ok=True)
        for name in GAME_FILES:
            write_new(target / name, (source / name).read_text(encoding="utf-8"), "games", lines)
        spec = json.loads((target / "clemgame.json").read_text(encoding="utf-8"))
        entries += [dict(entry, game_path=str(target)) for entry in (spec if isinstance(spec, list) else [spec])]
    merge_into(registry_dir / GAMES_FILE, entries, "game_name", "games", lines)
    return lines


def _folder(folder: Path) -> Path:
    folder = Path(folder)
    if not folder.is_dir():
        raise UserError(f"{folder}: not a folder")
    return folder


def run(args) -> int:
    lines = register(args.dir)
    for line in lines:
        print(line)
    if not lines and not args.quiet:
        print(f"{args.dir}: sartco's models and backends already registered")
    return 0


def run_games(args) -> int:
    lines = install_games(args.dir, Path.cwd())
    for line in lines:
        print(line)
    if not lines and not args.quiet:
        print(f"{args.dir}: sartco's games already there")
    return 0
