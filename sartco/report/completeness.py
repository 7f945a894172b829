"""Is a results folder complete? Every (model, game, experiment) of a results folder against the
episodes of the instance file it was played from (sartco.clem.core.runs.played_instance_file:
run.json's, else the game entry's default file).

What counts as missing, errored, unscored or unreadable: sartco.clem.tooling.completeness.
The experiments checked: with run.json those its sessions chose (all of the file when one of
them had no -e; a resume chooses nothing new), without it those with a folder. `sartco report` writes completeness.md / .csv,
marks each incomplete cell with INCOMPLETE_MARK and exits with INCOMPLETE_STATUS; `sartco resume`
plays the missing and errored episodes again and scores the unscored ones.
"""
from __future__ import annotations

import sys
from collections import Counter
from dataclasses import dataclass, field
from pathlib import Path

from sartco.clem.core.errors import ProvenanceError
from sartco.clem.core.runs import selecting
from sartco.clem.tooling.completeness import INCOMPLETE_STATUS, PROBLEMS, Unverifiable, check_game
from sartco.errors import UserError

from .files import markdown_table, write_csv

INCOMPLETE_MARK = "†"


@dataclass
class Completeness:
    expected: dict[tuple, int] = field(default_factory=dict)   # (model, game, experiment) -> episodes
    problems: list[dict] = field(default_factory=list)         # model, game, experiment, game_id, problem
    runs: dict[tuple, dict] = field(default_factory=dict)      # (model, game) -> run.json
    unverifiable: list[str] = field(default_factory=list)      # folders whose instance file is unknown
    results: Path = Path("results")                             # the results folder checked

    def scored(self, key: tuple) -> int:
        return self.expected[key] - sum(1 for p in self.problems if (p["model"], p["game"], p["experiment"]) == key)

    def annotate(self, episodes: list[dict]) -> None:
        """Give every episode row of the report its experiment's expected and scored counts."""
        for e in episodes:
            key = (e["model"], e["game"], e["experiment"])
            e["experiment_counts"] = (key, self.expected[key], self.scored(key)) if key in self.expected else None


def cell(episodes: list[dict]) -> dict:
    """episodes_expected and episodes_scored of a table cell (episode rows given Completeness.annotate;
    an episode of an experiment that was not checked counts as expected and scored)."""
    counts = {e["experiment_counts"][0]: e["experiment_counts"][1:] for e in episodes if e.get("experiment_counts")}
    unchecked = sum(1 for e in episodes if not e.get("experiment_counts"))
    return {"episodes_expected": unchecked + sum(n for n, _ in counts.values()),
            "episodes_scored": unchecked + sum(k for _, k in counts.values())}


def check(results: Path, games: list[str] | None, game_names: set[str]) -> Completeness:
    """Every results/<model>/<game> folder of `games` (None: all) whose game is one of
    `game_names` (the SARTCo games found in the folder) or has a SARTCo run.json."""
    out = Completeness(results=Path(results))
    for game_dir in sorted(p for p in Path(results).glob("*/*") if p.is_dir()):
        if (games and game_dir.name not in games) or (
                game_dir.name not in game_names and not (game_dir / "run.json").is_file()):
            continue
        try:
            expected, problems, run = check_game(game_dir)
        except ProvenanceError as exc:
            raise UserError(str(exc)) from None
        except Unverifiable as exc:
            out.unverifiable.append(str(exc))
            continue
        model, game = game_dir.parent.name, game_dir.name
        out.expected.update({(model, game, x): n for x, n in expected.items()})
        out.problems += problems
        if run is not None:
            out.runs[(model, game)] = run
    return out


def id_ranges(ids: list[int]) -> str:
    """1, 2, 3, 7 -> "1-3, 7"."""
    spans, ids = [], sorted(ids)
    for i in ids:
        if spans and spans[-1][1] == i - 1:
            spans[-1][1] = i
        else:
            spans.append([i, i])
    return ", ".join(str(a) if a == b else f"{a}-{b}" for a, b in spans)


def _ids(found: list[dict]) -> str:
    """"missing 3-5; unscored 9" for the problems of one experiment."""
    return "; ".join(f"{p} {id_ranges([f['game_id'] for f in found if f['problem'] == p])}"
                     for p in PROBLEMS if any(f["problem"] == p for f in found))


def write(result: Completeness, out: Path) -> list[str]:
    """completeness.md / .csv in `out`; the files written."""
    header = ["model", "game", "experiment", "episodes_expected", "episodes_scored", *PROBLEMS, "ids"]
    rows = []
    for key in sorted(result.expected):
        found = [p for p in result.problems if (p["model"], p["game"], p["experiment"]) == key]
        counts = Counter(p["problem"] for p in found)
        rows.append({"model": key[0], "game": key[1], "experiment": key[2],
                     "episodes_expected": result.expected[key], "episodes_scored": result.scored(key),
                     **{p: counts.get(p, 0) for p in PROBLEMS}, "ids": _ids(found)})
    write_csv(out / "completeness.csv", header, rows)
    incomplete = [r for r in rows if r["episodes_scored"] < r["episodes_expected"]]
    md = "# Completeness (episodes of the instance file against the results folder)\n\n"
    md += (f"{len(incomplete)} of {len(rows)} experiments incomplete ({INCOMPLETE_MARK} in the tables): "
           f"`sartco resume` plays the missing and errored episodes, `clem score` scores the unscored.\n\n"
           if incomplete else f"All {len(rows)} experiments complete.\n\n")
    md += markdown_table(header, [[r[h] for h in header] for r in incomplete or rows])
    if result.unverifiable:
        md += "\nNot checked (which episodes they should hold is unknown):\n\n" + "".join(
            f"- {note}\n" for note in result.unverifiable)
    md += runs_markdown(result.runs)
    (out / "completeness.md").write_text(md, encoding="utf-8")
    return ["completeness.md", "completeness.csv"]


def finish(result: Completeness, out: Path, written: list[str]) -> int:
    """Print the provenance of each run and what is incomplete (ids), head every Markdown table
    of an incomplete folder with a warning; the exit status of `sartco report`."""
    for (model, game), run in sorted(result.runs.items()):
        print(f"  run {model} / {game}: played with {played_with(run)}; {run['instance_file']['path']} sha256 "
              f"{run['instance_file']['sha256'][:12]}; {software(run)}; {run.get('start')} .. {run.get('end')}")
    for note in result.unverifiable:
        print(f"  not checked: {note}")
    incomplete = [k for k in sorted(result.expected) if result.scored(k) < result.expected[k]]
    if not incomplete:
        return 0
    banner = (f"> {INCOMPLETE_MARK} Incomplete results: {len(incomplete)} experiments have missing, errored, "
              f"unscored or unreadable episodes (completeness.md); cells marked {INCOMPLETE_MARK} count fewer "
              f"episodes than their instance file.\n\n")
    for name in written:
        if name.endswith(".md") and name != "completeness.md":
            path = out / name
            path.write_text(banner + path.read_text(encoding="utf-8"), encoding="utf-8")
    lines = []
    for key in incomplete:
        found = [p for p in result.problems if (p["model"], p["game"], p["experiment"]) == key]
        lines.append(f"  {' / '.join(key)}: {result.scored(key)} of {result.expected[key]} scored; {_ids(found)}")
    fixes = sorted({f"sartco resume -r {result.results} -g {game} -m {model}" for model, game, _ in incomplete})
    print(f"sartco report: INCOMPLETE ({len(result.problems)} episodes; exit status {INCOMPLETE_STATUS}):\n"
          + "\n".join(lines) + "\n  to complete: " + "; ".join(fixes), file=sys.stderr)
    return INCOMPLETE_STATUS


def played_with(run: dict) -> str:
    """The settings a run.json's numbers come from: temperature, max_tokens and batch size with the
    experiments each was chosen for (-e; "all experiments"), one group per distinct setting."""
    groups: dict[tuple, list[str]] = {}
    for session in selecting(run):
        generation = session.get("generation") or {}
        key = tuple(_recorded(v) for v in (generation.get("temperature"), generation.get("max_tokens"),
                                           session.get("batch_size")))
        groups.setdefault(key, []).append(session.get("experiment") or "all experiments")
    return "; ".join(f"temperature {t}, max_tokens {m}, batch size {b} ({', '.join(dict.fromkeys(x))})"
                     for (t, m, b), x in groups.items()) or "no session recorded"


def _recorded(value) -> str:
    return "not recorded" if value is None else str(value)


def software(run: dict) -> str:
    """The interpreter and the versions of the packages a score depends on, from a run.json."""
    python = (run.get("python") or {}).get("version", "not recorded")
    packages = run.get("packages") or {"sartco-bench": run.get("sartco_version"), "clemcore": run.get("clemcore_version")}
    return (f"python {python}, " + ", ".join(f"{k} {_recorded(v)}" for k, v in packages.items())
            + f", git {(run.get('git_commit') or 'none')[:12]}")


RUN_HEADER = ["model", "game", "instance file", "sha256", "played with", "software", "start", "end", "sessions",
              "played"]


def run_row(model: str, game: str, run: dict) -> list:
    """The provenance of one run.json, in RUN_HEADER's order."""
    return [model, game, run["instance_file"]["path"], run["instance_file"]["sha256"][:12], played_with(run),
            software(run), run.get("start"), run.get("end"), run["counts"]["sessions"], run["counts"]["episodes_played"]]


def runs_markdown(runs: dict[tuple, dict]) -> str:
    """The provenance of each (model, game): one line per run.json."""
    if not runs:
        return ""
    rows = [run_row(model, game, run) for (model, game), run in sorted(runs.items())]
    return "\n## Provenance (run.json per model and game)\n\n" + markdown_table(RUN_HEADER, rows)


def mark(value, row: dict):
    """A table value with INCOMPLETE_MARK when its cell is incomplete."""
    if row.get("episodes_scored", 0) < row.get("episodes_expected", 0):
        return f"{value:.2f}{INCOMPLETE_MARK}" if isinstance(value, float) else f"{value}{INCOMPLETE_MARK}"
    return value
