"""cobot_describe, all of its own code: the game master and benchmark, the describer, the dialogue
and its built-in players, its instance files (see sartco.games)."""
