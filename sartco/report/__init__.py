"""`sartco report`: paper-style tables from a clemcore results folder (the top layer: it reads the
scores.json files the games' scorers wrote, by the names in sartco.episode).

tables         Table 3 of our protocol, the ablations, the feedback experiments, error families
paper_table    the paper protocol's Table 3 beside the paper's own figures
dialogue_table cobot_describe's dialogue scores
harness_table  the harness_error episodes per model and game (left out of the other tables; exit 3)
"""
