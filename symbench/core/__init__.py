"""The benchmark itself. Nothing in here imports a plugin."""
