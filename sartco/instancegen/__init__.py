"""The instance files of both games, written by one command (`sartco instances MODE`, and the game
scripts games/*/instancegenerator.py with their old flags): sartco.instancegen.command (modes and
options), .options (defaults and bounds), .legacy (the scripts' flags). Each game's files are its own
package's (sartco.games.instruct.instancegenerator, sartco.games.describe.instancegenerator: one function per
instance file), over what both share (sartco.clem.core.instance_files: the generator class,
writing, the dataset's records).

One convention for every file of both games: game_id counts from 0 in each experiment (an episode
is its game, experiment and game_id), and experiments are named by sartco.dataset.experiment_name,
<cell>_<task>_<source>[_<variant>] (sb_so_first_order_template, rb_co_repetition_describer_clarify).
What a file records about its data differs by game: cobot_instruct's files record `dataset` as
dataset_info (version, source, seed, path, generator seed, examples); cobot_describe's record
`dataset` (version, seed, source, split) and a top-level `seed`.
"""
