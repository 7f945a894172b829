"""The paper protocol's game glue: cobot_instruct_paper's episodes in clemcore (see sartco.clem)."""
