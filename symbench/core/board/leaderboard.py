"""Aggregate result records into leaderboard tables (Markdown + CSV) and plots.

Records are grouped by dataset, training protocol, size, split, model, variant and backend
(a dataset belongs to one robot; a standard dataset id names its robot and preset); metrics
are averaged over seeds with their standard deviation and 95 % bootstrap interval, and each
(dataset, protocol, size, split) table is ranked by mean test torque RMSE, with rank bands
that join the models a paired test over seeds cannot tell apart (`statistics`). Protocols
and sizes (default, or matched to N parameters: `board.sizes`) are never mixed in one table:
each has its own sections, and ranks never cross them. Every row shows the parameter count,
the gradient steps trained and why training stopped (records from before the `converge`
protocol were trained under the paper's rule; their stop reason follows from whether they
stopped before the epoch cap). Each robot's page has a section per dataset, so a robot's
standard data and its imported logs sit side by side, never mixed. Records of one dataset id
made on different contents (another version of the data) or with different presets (budgets)
are never mixed either: their numbers would not be comparable, so the aggregation refuses
and says why. Schema-1 (unsealed) records are still shown, so that old boards can be read;
publishing refuses them. Output file names come from record fields that the schema restricts
to safe identifiers.
"""

from __future__ import annotations

from collections import defaultdict
from collections.abc import Iterable
from pathlib import Path

import numpy as np
import pandas as pd
from pandas.api.typing import DataFrameGroupBy

from symbench.core.board.cells import cell_of
from symbench.core.board.claims import claims_markdown
from symbench.core.board.cost import cost_section
from symbench.core.board.plot_files import write_png
from symbench.core.board.plots import asymmetry_figure, sample_efficiency_figure
from symbench.core.board.series import asymmetry_series, sample_efficiency_panels
from symbench.core.board.sizes import (
    by_size,
    default_size,
    miss,
    miss_caption,
    miss_text,
    size_of,
    titled,
)
from symbench.core.board.statistics import mean_interval, rank_bands
from symbench.core.board.summary import headline
from symbench.core.common.atomic import write_text_atomic
from symbench.core.common.errors import SymbenchError
from symbench.core.robot.specs import split_variant
from symbench.core.runs.results import RecordV1, read_display_record

MIN_SEEDS = 3
RECORDS = "records"  # a board's folder of records, beside its tables
# (evaluator, metric) pairs shown in the tables when present, with their column names
COLUMNS = {
    ("torque-error", "rmse"): "rmse_Nm",
    ("torque-error", "nrmse"): "nrmse",
    ("equivariance", "max_rel_error"): "equiv_err",
    ("invariance", "max_rel_change"): "invar_change",
    # closed loop at the headline PD fraction (the evaluator's `pd_*` metrics): success,
    # seconds held, joint tracking RMSE and the score between floor (0) and oracle (1)
    ("closed-loop", "pd_success_rate"): "cl_success",
    ("closed-loop", "pd_time_to_failure_s"): "cl_held_s",
    ("closed-loop", "pd_joint_rmse_rad"): "cl_rmse_rad",
    ("closed-loop", "pd_normalized_score"): "cl_score",
    # the continuous tracking score between floor (0) and oracle (1), pushed references
    # (dataset v7 on; earlier records lack it and their tables show no such column)
    ("closed-loop", "pd_tracking_score"): "cl_tracking",
    # the dataset's own torque asymmetry (data-symmetry evaluator): the same for every model
    ("data-symmetry", "tau_rel_error"): "data_tau_asym",
}


def load_records(folder: Path) -> list[tuple[Path, RecordV1]]:
    """Every *.json record in `folder` (not its subfolders, which hold checkpoints),
    validated and, from schema 2 on, matching its seal; sorted by path for reproducibility."""
    paths = sorted(Path(folder).glob("*.json"))
    if not paths:
        raise SymbenchError(f"no result records (*.json) under {folder}")
    return [(p, read_display_record(p)) for p in paths]


def check_consistent(records: Iterable[tuple[Path, RecordV1]]) -> None:
    """One content hash and one preset per dataset id, or an error."""
    hashes: dict[str, dict[str, Path]] = defaultdict(dict)
    presets: dict[str, dict[str, Path]] = defaultdict(dict)
    for path, r in records:
        hashes[r.dataset.id].setdefault(r.dataset.content_hash, path)
        presets[r.dataset.id].setdefault(r.dataset.preset, path)
    for did, by_hash in hashes.items():
        if len(by_hash) > 1:
            examples = ", ".join(f"{p.name} ({h[:12]}...)" for h, p in by_hash.items())
            raise SymbenchError(
                f"records of dataset {did} come from {len(by_hash)} different datasets "
                f"({examples}); aggregate records of one dataset version only"
            )
    for did, by_preset in presets.items():
        if len(by_preset) > 1:
            examples = ", ".join(f"{p.name} ({name})" for name, p in by_preset.items())
            raise SymbenchError(
                f"records of dataset {did} were made with {len(by_preset)} presets "
                f"({examples}); aggregate records of one preset per dataset only"
            )


def _stopped_by(record: RecordV1) -> str:
    """Why the training stopped, also for records from before `stopped_by` was recorded
    (all paper protocol: early means its overfitting rule, else the epoch cap)."""
    found = getattr(record.training, "stopped_by", None)
    if found:
        return str(found)
    return "overfitting-rule" if record.training.stopped_early else "epoch-cap"


def protocol_of(record: RecordV1) -> str:
    config = getattr(record.training, "config", None)
    return str(config.protocol) if config is not None else "paper"


def _flat(record: RecordV1) -> dict:
    steps = getattr(record.training, "steps", None)
    row = {
        "robot": record.robot,
        "split": record.split,
        "model": record.model.name,
        "variant": record.model.variant,
        "backend": record.model.backend,
        "seed": record.seed,
        "dataset": record.dataset.id,
        "preset": record.dataset.preset,
        "protocol": protocol_of(record),
        "size": size_of(record),
        "parameters": record.model.parameters,
        "learning_rate": record.model.learning_rate,
        "epochs": float(record.training.epochs),
        "steps": float(steps) if steps is not None else np.nan,
        "stopped_by": _stopped_by(record),
    }
    for (evaluator, metric), column in COLUMNS.items():
        value = record.metrics.get(evaluator, {}).get(metric)
        row[column] = float(value) if isinstance(value, (int, float)) else np.nan
    return row


def aggregate(records: list[tuple[Path, RecordV1]]) -> pd.DataFrame:
    """Mean, standard deviation and 95 % bootstrap interval over seeds per (dataset, protocol,
    size, split, model, variant, backend), ranked within each (dataset, protocol, size,
    split) with rank bands; `parameters_miss` is a matched size's relative miss; the
    dataset's robot and preset are columns too, and `per_seed` holds each metric's values
    by seed (for the plots' dots, the bands and the aggregate across robots)."""
    check_consistent(records)
    runs = pd.DataFrame([_flat(r) for _, r in records])
    run = ["dataset", "protocol", "size", "split", "model", "variant", "backend", "seed"]
    duplicate = runs.duplicated(run, keep=False)
    if duplicate.any():
        first = runs[duplicate].iloc[0]
        same = (runs[run] == first[run]).all(axis=1)
        files = " and ".join(str(p) for (p, _), s in zip(records, same) if s)
        raise SymbenchError(
            f"two records for the same run ({first['dataset']} {first['protocol']} "
            f"{first['size']} size {first['split']} {first['model']} {first['variant']} "
            f"{first['backend']} seed {first['seed']}): {files}; keep one"
        )
    # robot and preset follow from the dataset (one content, one preset per id)
    keys = [
        *["robot", "dataset", "preset", "protocol", "size"],
        *["split", "model", "variant", "backend"],
    ]
    missing = runs.rmse_Nm.isna()
    if missing.any():
        names = ", ".join(sorted(str(p.name) for (p, _), m in zip(records, missing) if m)[:5])
        raise SymbenchError(
            f"records without a torque-error RMSE cannot be ranked ({names}); "
            "run them with the torque-error evaluator"
        )
    # epochs, steps and the stop reason show how long each model trained and why it ended
    metrics = [c for c in COLUMNS.values() if runs[c].notna().any()] + ["epochs"]
    metrics += ["steps"] if runs.steps.notna().any() else []
    grouped = runs.groupby(keys, sort=True)
    _check_one_rate(grouped, records)
    table = grouped.agg(
        seeds=("seed", "nunique"),
        parameters=("parameters", "first"),
        learning_rate=("learning_rate", "first"),
        stopped_by=("stopped_by", _counts),
    )
    for m in metrics:
        table[f"{m}_mean"] = grouped[m].mean()
        table[f"{m}_std"] = grouped[m].std(ddof=1)
        bounds = [mean_interval(part.to_numpy()) for _, part in grouped[m]]
        table[f"{m}_ci_low"] = [low for low, _ in bounds]
        table[f"{m}_ci_high"] = [high for _, high in bounds]
    table["per_seed"] = pd.Series(
        [
            {m: dict(zip(part.seed, part[m])) for m in metrics}
            for _, part in grouped[["seed", *metrics]]
        ],
        index=table.index,
        dtype=object,
    )
    table = table.reset_index()
    table["parameters_miss"] = [
        miss(int(p), str(s)) for p, s in zip(table.parameters, table["size"])
    ]
    tables = table.groupby(["dataset", "protocol", "size", "split"])
    table["rank"] = tables["rmse_Nm_mean"].rank(method="min").astype(int)
    table["rank_band"] = tables["per_seed"].transform(
        lambda part: rank_bands([seeds["rmse_Nm"] for seeds in part])
    )
    order = [
        *["robot", "dataset", "protocol", "size", "split"],
        *["rank", "model", "variant", "backend"],
    ]
    return table.sort_values(order).reset_index(drop=True)


def _check_one_rate(grouped: DataFrameGroupBy, records: list[tuple[Path, RecordV1]]) -> None:
    """One learning rate per entry: seeds trained at different rates (a robot tuned between
    two sweeps) are two configurations, not one mean."""
    for key, part in grouped:
        rates = sorted(set(part.learning_rate))
        if len(rates) > 1:
            names = [records[part.index[part.learning_rate == r][0]][0].name for r in rates]
            raise SymbenchError(
                f"the seeds of {' '.join(str(k) for k in key)} were trained at learning "
                f"rates {', '.join(f'{r:g}' for r in rates)} ({' and '.join(names)}): "
                "keep the records of one rate"
            )


def _counts(reasons: pd.Series) -> str:
    """'overfitting-rule 2, epoch-cap 1': why the seeds' trainings stopped."""
    counts = reasons.value_counts()
    return ", ".join(f"{r} {counts[r]}" for r in sorted(counts.index))


def markdown(table: pd.DataFrame, robot: str) -> str:
    """One robot's leaderboard: a section per dataset, protocol and size (default first),
    in it one per split, rows ranked by RMSE."""
    metrics = [c[: -len("_mean")] for c in table.columns if c.endswith("_mean")]
    lines = [
        f"# {robot}",
        "",
        "Every metric: mean [95 % bootstrap interval] over seeds. Rank: a band joining the "
        "models that a paired t-test over seeds (log test RMSE, p < 0.05) cannot tell apart "
        "(docs/leaderboard-protocol.md#statistics).",
        "",
    ]
    for (did, preset, protocol), data in table[table.robot == robot].groupby(
        ["dataset", "preset", "protocol"], sort=True
    ):
        for size, part in by_size(data):
            lines += [titled(f"## Dataset {did}, preset {preset}, {protocol} protocol", size), ""]
            caption = miss_caption(part, size)
            lines += [caption, ""] if caption else []
            lines += _split_tables(part, metrics)
    return "\n".join(lines)


def _split_tables(table: pd.DataFrame, metrics: list[str]) -> list[str]:
    lines: list[str] = []
    for split, part in table.groupby("split", sort=True):
        lines += [
            f"### {split}",
            "",
            "| rank | model | variant | backend | seeds | parameters | learning rate | "
            + " | ".join(metrics)
            + " | stopped by |",
            "|---|---|---|---|---|---|---|" + "---|" * len(metrics) + "---|",
        ]
        for _, row in part.iterrows():
            cells = [cell_of(row, m) for m in metrics]
            flag = "" if row.seeds >= MIN_SEEDS else f" (<{MIN_SEEDS})"
            off = miss_text(int(row.parameters), str(row["size"]))
            count = f"{row.parameters} ({off})" if off else str(row.parameters)
            lines.append(
                f"| {row.rank_band} | {row.model} | {row.variant} | {row.backend} "
                f"| {row.seeds}{flag} | {count} | {row.learning_rate:g} | "
                + " | ".join(cells)
                + f" | {row.stopped_by} |"
            )
        lines.append("")
    return lines


def write_leaderboard(results: Path, out: Path) -> list[Path]:
    """Aggregate the records under `results` into tables and plots under `out`."""
    return write_tables(load_records(results), out)


def write_tables(records: list[tuple[Path, RecordV1]], out: Path) -> list[Path]:
    """Aggregate `records` into tables and plots under `out`."""
    table = aggregate(records)
    written = []
    csv = out / "leaderboard.csv"
    flat = table.drop(columns="per_seed")
    write_text_atomic(csv, flat.to_csv(index=False, float_format="%.6g"))
    written.append(csv)
    summary = out / "summary.md"
    write_text_atomic(
        summary, headline(table).rstrip("\n") + "\n\n" + "\n".join(cost_section(records))
    )
    written.append(summary)
    claims = out / "claims.md"
    write_text_atomic(claims, claims_markdown(table))
    written.append(claims)
    plotted = default_size(table)  # a plot's series would mix sizes
    for robot in sorted(table.robot.unique()):
        md = out / f"{robot}.md"
        write_text_atomic(md, markdown(table, robot))
        written.append(md)
        panels = sample_efficiency_panels(plotted, robot)
        if panels:
            png = out / f"{robot}-sample-efficiency.png"
            write_png(sample_efficiency_figure(panels), png)
            written.append(png)
    for base in sorted({split_variant(r)[0] for r in plotted.robot.unique()}):
        curves, data = asymmetry_series(plotted, base)
        if curves:
            png = out / f"{base}-asymmetry.png"
            write_png(asymmetry_figure(curves, data, f"{base}: error against asymmetry"), png)
            written.append(png)
    return written
