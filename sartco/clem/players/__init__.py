"""The players and the built-in players' answer sources both games use (see sartco.clem)."""
