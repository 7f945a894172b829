"""The game core shared by every SARTCo game that ends in a build: reading answers, building,
outcomes, scoring, the benchmark base, transcripts, score cards, pictures (see sartco.clem)."""
