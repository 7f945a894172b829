"""cobot_instruct as clemcore loads it: clemcore runs this file by path and plays the one
GameBenchmark subclass among its module's members. The game is its package, sartco.games.instruct
(master: the game master and this benchmark; scorer, instancegenerator, fresh, paper, training), so this
file names the benchmark and nothing else."""
from sartco.games.instruct.master import CobotInstructBenchmark

__all__ = ["CobotInstructBenchmark"]
