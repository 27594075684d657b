"""The description a saved model carries (`TrainedModel.describe`), validated when loaded: a
checkpoint's content hash proves it intact, not that symbench wrote it, so a crafted file
with a missing or mistyped field is refused naming the field."""

from __future__ import annotations

from typing import Annotated, Any

from pydantic import BaseModel, ConfigDict, Field


class DimsDescription(BaseModel):
    model_config = ConfigDict(strict=True, frozen=True)

    view: str
    variant: str
    n_legs: Annotated[int, Field(ge=1, le=1000)]
    inputs: dict[str, list[int]]


class ModelDescription(BaseModel):
    """The fields `TrainedModel.load` uses (others are kept for readers, not checked)."""

    model_config = ConfigDict(strict=True, frozen=True, extra="allow")

    model: str
    backend: str
    dims: DimsDescription
    hyper: dict[str, Any]
    config: dict[str, Any]
    history: dict[str, list[float]]
    best_epoch: int
    stopped: str
