"""cobot_instruct's instance files: `sartco instances instruct...` with the flags this script always
took (sartco.games.instruct.instancegenerator: one function per file; sartco.instancegen: the modes;
sartco.instancegen.legacy: the flags).

    python games/cobot_instruct/instancegenerator.py     # in/instances.json, instances_ablations.json,
                                                         # instances_feedback.json, instances_smoke.json
    python games/cobot_instruct/instancegenerator.py --published instances/published
    python games/cobot_instruct/instancegenerator.py --protocol paper [--paper-data DIR]
    python games/cobot_instruct/instancegenerator.py --fresh SEED [--fresh-episodes N]
    python games/cobot_instruct/instancegenerator.py --train [--train-episodes N]
    python games/cobot_instruct/instancegenerator.py --describers DIR
"""
import sys
from pathlib import Path

from sartco.instancegen.command import script_main


def main(argv=None) -> int:
    return script_main("cobot_instruct", Path(__file__).resolve().parent, argv)


if __name__ == "__main__":
    sys.exit(main())
