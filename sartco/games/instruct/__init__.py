"""cobot_instruct, all of its own code: the game master and benchmark, its episodes and instance
files, fresh boards, the training environment and the paper protocol's glue (see sartco.games)."""
