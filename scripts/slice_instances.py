"""Write a slice of a game's instances: the first N episodes of every main experiment (the
val-split ablations, experiments with an "ablation" field, are left out).

    python scripts/slice_instances.py games/cobot_instruct/in/instances.json N OUT.json

Used by scripts/local_model.sh to give a slow local model a few episodes per experiment family.
"""
import json
import sys
from pathlib import Path


def main(src: str, n: str, out: str) -> None:
    data = json.loads(Path(src).read_text(encoding="utf-8"))
    data["experiments"] = [e for e in data["experiments"] if not e.get("ablation")]
    for experiment in data["experiments"]:
        experiment["game_instances"] = experiment["game_instances"][: int(n)]
    Path(out).write_text(json.dumps(data, ensure_ascii=False, indent=1) + "\n", encoding="utf-8")


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    main(*sys.argv[1:])
