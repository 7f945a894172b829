"""cobot_describe's own logic: the describer, the dialogue and its built-in players (see sartco.clem)."""
