"""The instance files of both games, written by one command (`sartco instances MODE`, and the game
scripts games/*/instancegenerator.py with their old flags): sartco.instancegen.command (modes and
options), .instruct and .describe (one function per instance file), .common (the generator class,
writing, the dataset's records), .options (defaults and bounds), .legacy (the scripts' flags).

Conventions kept from the two generators because changing them would change the files' bytes:
cobot_instruct counts game_id from 0 in each experiment and names experiments by BoardKind.cell
(sb_so, rb_so, rb_co), its files record `dataset` as dataset_info (version, source, seed, path,
generator seed, examples); cobot_describe counts game_id over both of its files and names
experiments by BoardKind.experiment (simple_boards, ...), recording `dataset` (version, seed,
source, split) and a top-level `seed`.
"""
