"""Built-in PyTorch models (imports torch only when a network is built)."""

from symbench import hookimpl
from symbench.plugins.zoo import model_entries


@hookimpl
def symbench_models() -> list:
    return model_entries("torch", __name__)
