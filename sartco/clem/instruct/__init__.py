"""cobot_instruct's own logic: its instance generators and its training environment (see sartco.clem)."""
