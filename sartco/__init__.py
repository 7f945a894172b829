"""SARTCo bench: the world, the sandboxed executor, instances and scores shared by both games."""
