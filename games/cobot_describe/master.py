"""cobot_describe as clemcore loads it: clemcore runs this file by path and plays the one
GameBenchmark subclass among its module's members. The game is its package, sartco.games.describe
(master: the game master and this benchmark; scorer, players, instancegenerator, dialogue, turns,
erring_dialogue), so this file names the benchmark and nothing else."""
from sartco.games.describe.master import CobotDescribeBenchmark

__all__ = ["CobotDescribeBenchmark"]
