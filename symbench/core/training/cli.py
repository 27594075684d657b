"""`symbench export`: a trained model as a file a controller outside Python can load."""

from __future__ import annotations

from pathlib import Path

import click

from symbench.core.common.console import StdoutConsole
from symbench.core.common.errors import SymbenchError


@click.command("export")
@click.argument("model_folder", type=click.Path(path_type=Path))
@click.option(
    "--onnx",
    "onnx_file",
    type=click.Path(path_type=Path, dir_okay=False),
    required=True,
    help="The ONNX file to write (raw inputs by view key in, torques in N m out).",
)
@click.option(
    "--batch",
    type=click.IntRange(min=1),
    default=None,
    help="Fix the batch size (faster calls of that size: ONNX Runtime folds the shape "
    "arithmetic away); default: any batch size.",
)
def export(model_folder: Path, onnx_file: Path, batch: int | None) -> None:
    """Write the trained torch model saved in MODEL_FOLDER (model.safetensors: a run's under
    OUTPUT/checkpoints/<run key>/<data hash>/<split>__<variant>/best) as one ONNX file, its
    normalization included, after checking ONNX Runtime's torques against the model's."""
    from symbench.core.training.onnx_export import write_onnx
    from symbench.core.training.trained_model import TENSORS, TrainedModel

    if not (model_folder / TENSORS).is_file():
        raise SymbenchError(f"{model_folder} holds no {TENSORS}: give the folder of a saved model")
    model = TrainedModel.load(model_folder)
    difference, compared = write_onnx(model, onnx_file, batch)
    inputs = ", ".join(f"{k} {tuple(shape)}" for k, shape in model.dims.inputs)
    rows = "any number of rows" if batch is None else f"{batch} row{'s' * (batch > 1)}"
    StdoutConsole().print(
        f"wrote {onnx_file}: {model.entry.name} ({model.n_params} parameters), {rows} per call, "
        f"inputs {inputs} per row, torques (legs, 3) in N m; largest |ONNX Runtime - model| "
        f"over {compared} rows {difference:.2g} N m",
        highlight=False,
    )
