"""Small networks so that the model tests stay fast (JAX compiles add up)."""

SMALL = {
    "ffnn": {"width": 32, "layers": 2},
    "ffnn-leg": {"width": 32, "layers": 2},
    "gnn": {"edge": 16, "node": 8, "glob": 8, "steps": 1},
    "sdgnn": {"edge": 16, "node": 8, "glob": 8, "steps": 1},
    "sdnn": {"latent": 32, "steps": 1},
}
MODELS = tuple(SMALL)
BACKENDS = ("torch", "jax")
