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
def export(model_folder: Path, onnx_file: Path) -> None:
    """Write the trained torch model saved in MODEL_FOLDER (model.safetensors: a run's under
    OUTPUT/checkpoints/<run key>/<data hash>/<split>__<variant>/best) as one ONNX file, its
    normalization included, after checking ONNX Runtime's torques against the model's."""
    from symbench.core.training.onnx_export import PARITY_ROWS, write_onnx
    from symbench.core.training.trained_model import TENSORS, TrainedModel

    if not (model_folder / TENSORS).is_file():
        raise SymbenchError(f"{model_folder} holds no {TENSORS}: give the folder of a saved model")
    model = TrainedModel.load(model_folder)
    difference = write_onnx(model, onnx_file)
    inputs = ", ".join(f"{k} {tuple(shape)}" for k, shape in model.dims.inputs)
    StdoutConsole().print(
        f"wrote {onnx_file}: {model.entry.name} ({model.n_params} parameters), inputs {inputs} "
        f"per row, torques (legs, 3) in N m; largest |ONNX Runtime - model| over "
        f"{PARITY_ROWS} rows {difference:.2g} N m",
        highlight=False,
    )
