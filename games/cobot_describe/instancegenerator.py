"""cobot_describe's instance files: `sartco instances describe` with the flags this script always
took (sartco.games.describe.instancegenerator: the experiments and modes, one function per file).

    python games/cobot_describe/instancegenerator.py [--dataset instances/v1] [--seed 42]
           [--examples 5] [--questions 2] [--corrections 3] [--slice N]
"""
import sys
from pathlib import Path

from sartco.instancegen.command import script_main


def main(argv=None) -> int:
    return script_main("cobot_describe", Path(__file__).resolve().parent, argv)


if __name__ == "__main__":
    sys.exit(main())
