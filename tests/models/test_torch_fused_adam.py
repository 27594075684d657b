"""The torch trainer's Adam (`torch_adam.FusedAdam`) updates as `torch.optim.Adam(fused=True)`
does, to the last bit, and keeps its state in torch's layout."""

from __future__ import annotations

import pytest
import torch

from symbench.core.data.views.model_dims import dims_for
from symbench.core.plugin import registry
from symbench.core.training.backends.torch_adam import FusedAdam
from symbench.core.training.backends.torch_backend import build_network


def _trained(net: torch.nn.Module, step, x: torch.Tensor, rates: list[float]) -> None:
    for lr in rates:
        loss = net(x).square().mean()
        loss.backward()
        step(lr)


@pytest.mark.parametrize("name", ["sdgnn", "ffnn"])
def test_updates_and_state_are_torchs(name):
    """sdgnn's last node and global updates feed nothing, so their parameters never get a
    gradient: both optimizers skip them and create no state for them."""
    entry = registry.model(name, "torch")
    dims = dims_for(entry.view, entry.variant, 6)
    torch.manual_seed(0)
    ours, theirs = build_network(entry, dims, {}), build_network(entry, dims, {})
    theirs.load_state_dict(ours.state_dict())
    x = torch.randn(32, *dims.inputs[0][1])
    rates = [1e-3, 3e-3, 5e-4, 2e-3]

    adam = FusedAdam(list(ours.parameters()))

    def our_step(lr: float) -> None:
        adam.step(lr)
        adam.zero_grad()

    reference = torch.optim.Adam(theirs.parameters(), fused=True)

    def their_step(lr: float) -> None:
        reference.param_groups[0]["lr"] = lr
        reference.step()
        reference.zero_grad(set_to_none=True)

    _trained(ours, our_step, x, rates)
    _trained(theirs, their_step, x, rates)
    for (key, a), b in zip(ours.state_dict().items(), theirs.state_dict().values(), strict=True):
        assert torch.equal(a, b), key
    expected = reference.state_dict()["state"]
    assert sorted(adam.state_dict()) == sorted(expected)
    if name == "sdgnn":
        assert len(expected) < len(list(ours.parameters()))
    for i, state in expected.items():
        assert adam.state_dict()[i].keys() == state.keys()
        for key, value in state.items():
            assert torch.equal(adam.state_dict()[i][key], value), (i, key)
