"""The plots' layout and files: the legend beside the axes, never on the data; a line never
joined across an x where its entry has no record; the site's SVG the same bytes on every
build; human axis labels; the alt text saying the result."""

from __future__ import annotations

import math
from pathlib import Path

import matplotlib
import numpy as np
import pytest
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.container import BarContainer
from matplotlib.figure import Figure

from symbench.core.board.palette import colour_of
from symbench.core.board.plot_files import write_png, write_svg
from symbench.core.board.plots import (
    Series,
    Spread,
    asymmetry_figure,
    bars_figure,
    sample_efficiency_figure,
    sample_efficiency_png,
)
from symbench.core.board.site.alt_text import ranking


def spread(mean: float) -> Spread:
    return Spread(mean, mean * 0.9, mean * 1.1, (mean * 0.9, mean, mean * 1.1))


# converge at every fraction, cosine missing the middle one
CURVES = [
    Series(
        "sdnn",
        "sdnn (acc, torch, converge)",
        {0.1: spread(0.3), 0.5: spread(0.2), 1.0: spread(0.1)},
    ),
    Series("sdnn", "sdnn (acc, torch, cosine)", {0.1: spread(0.25), 1.0: spread(0.08)}),
    Series(
        "ffnn",
        "ffnn (acc, torch, converge)",
        {0.1: spread(0.9), 0.5: spread(0.7), 1.0: spread(0.5)},
    ),
]
BARS = [
    Series("gnn", "gnn (acc, torch)", {"iid": spread(0.6), "unseen-heading": spread(0.4)}),
    Series("sdnn", "sdnn (acc, torch)", {"iid": spread(0.9)}),
    Series("sdnn", "sdnn (acc, jax)", {"iid": spread(0.8), "unseen-heading": spread(0.5)}),
]


def figures() -> dict[str, Figure]:
    return {
        "curves": sample_efficiency_figure({"hexa: sample efficiency": CURVES}),
        # two datasets' panels sharing one entry: the legend has each entry once
        "panels": sample_efficiency_figure({"small": CURVES[:2], "paper": CURVES[1:]}),
        "bars": bars_figure(BARS, ["iid", "unseen-heading"], "closed-loop score", "t", 1.0),
        "asymmetry": asymmetry_figure(CURVES, ([0.0, 0.1], [1e-3, 0.05]), "hexa: asymmetry"),
    }


def overlaps(a, b) -> bool:
    return a.x0 < b.x1 and b.x0 < a.x1 and a.y0 < b.y1 and b.y0 < a.y1


def legend_on_axes(fig: Figure) -> list[bool]:
    """Whether each legend of the figure covers any of its axes' data area."""
    canvas = FigureCanvasAgg(fig)
    canvas.draw()
    renderer = canvas.get_renderer()
    legends = fig.legends + [ax.get_legend() for ax in fig.axes if ax.get_legend()]
    return [
        any(
            overlaps(legend.get_window_extent(renderer), ax.get_window_extent(renderer))
            for ax in fig.axes
        )
        for legend in legends
    ]


@pytest.mark.parametrize("kind", ["curves", "panels", "bars", "asymmetry"])
def test_the_legend_sits_beside_the_axes(kind):
    fig = figures()[kind]
    assert legend_on_axes(fig) == [False]
    labels = [t.get_text() for t in fig.legends[0].get_texts()]
    expected = CURVES if kind != "bars" else BARS
    assert labels == [s.label for s in expected]


def test_the_legend_check_can_fail():
    fig = figures()["curves"]
    fig.axes[0].legend()  # matplotlib's own placement: inside the axes
    assert legend_on_axes(fig) == [False, True]


def test_a_line_breaks_where_its_entry_has_no_record():
    ax = figures()["curves"].axes[0]
    lines = {c.get_label(): c.lines[0] for c in ax.containers}
    assert list(lines["sdnn (acc, torch, converge)"].get_xdata()) == [0.1, 0.5, 1.0]
    cosine = np.asarray(lines["sdnn (acc, torch, cosine)"].get_ydata(), dtype=float)
    assert np.isnan(cosine[1]) and not np.isnan(cosine[[0, 2]]).any()  # not joined over 0.5
    # each point keeps its marker, so an isolated one still shows
    assert lines["sdnn (acc, torch, cosine)"].get_marker() != "None"


def test_a_models_second_entry_differs_by_marker_and_line_not_colour():
    ax = figures()["curves"].axes[0]
    converge, cosine, ffnn = (c.lines[0] for c in ax.containers)
    assert converge.get_color() == cosine.get_color() != ffnn.get_color()
    assert converge.get_marker() != cosine.get_marker()
    assert converge.get_linestyle() != cosine.get_linestyle()
    bars = [c for c in figures()["bars"].axes[0].containers if isinstance(c, BarContainer)]
    assert [b.patches[0].get_hatch() for b in bars] == ["", "", "//"]  # a model's first: plain
    assert bars[1].patches[0].get_facecolor() == bars[2].patches[0].get_facecolor()


def test_axis_labels_are_words_not_column_names():
    for fig in figures().values():
        for ax in fig.axes:
            for label in (ax.get_xlabel(), ax.get_ylabel()):
                assert "_" not in label and "CI" not in label, label
    ax = figures()["curves"].axes[0]
    assert ax.get_ylabel() == "test torque RMSE (N m, log scale)"


def test_a_log_axis_puts_each_value_at_its_power_of_ten():
    """The RMSE axes draw log10 of the values on a linear axis and label it as a log axis:
    a labelled tick at each power of ten in view, ticks at 2 to 9 times it, named when fewer
    than two powers are in view."""
    ax = figures()["curves"].axes[0]
    converge = next(c.lines[0] for c in ax.containers if "converge" in c.get_label())
    assert list(converge.get_ydata()) == [math.log10(v) for v in (0.3, 0.2, 0.1)]
    low, high = ax.get_ylim()
    assert low < math.log10(0.08 * 0.9) and high > math.log10(0.9 * 1.1)
    majors = {t.get_position()[1]: t.get_text() for t in ax.get_yticklabels()}
    powers = range(math.ceil(low), math.floor(high) + 1)
    assert majors == {k: f"$\\mathdefault{{10^{{{k}}}}}$" for k in powers} and len(powers) == 2
    minors = [t.get_position()[1] for t in ax.get_yticklabels(minor=True)]
    expected = [k + math.log10(m) for k in range(-2, 1) for m in range(2, 10)]
    assert minors == [y for y in expected if low <= y <= high]
    assert not any(t.get_text() for t in ax.get_yticklabels(minor=True))
    narrow = Series("sdnn", "sdnn (acc, torch)", {0.5: spread(0.04), 1.0: spread(0.03)})
    ax = sample_efficiency_figure({"t": [narrow]}).axes[0]
    assert not ax.get_yticklabels()  # no power of ten in view: every minor tick named
    named = [t.get_text() for t in ax.get_yticklabels(minor=True)]
    assert named == ["$\\mathdefault{3\\times10^{-2}}$", "$\\mathdefault{4\\times10^{-2}}$"]


def svg_of(tmp_path: Path, name: str) -> bytes:
    write_svg(figures()["curves"], tmp_path / name)
    return (tmp_path / name).read_bytes()


def test_the_svg_is_the_same_bytes_on_every_build(tmp_path):
    first = svg_of(tmp_path, "a.svg")
    assert first == svg_of(tmp_path, "b.svg")
    assert b"<dc:date>" not in first and b"Matplotlib v" not in first
    # the check can fail: matplotlib's own ids are drawn at random per file
    with matplotlib.rc_context({"svg.hashsalt": None}):
        figures()["curves"].savefig(tmp_path / "c.svg", metadata={"Date": None})
    assert (tmp_path / "c.svg").read_bytes() != first


def test_the_board_png_is_sharp_and_uncropped(tmp_path):
    from PIL import Image

    fig = figures()["curves"]
    write_png(fig, tmp_path / "p.png")
    with Image.open(tmp_path / "p.png") as image:
        width, _ = image.size
        dpi = image.info["dpi"][0]
    assert math.isclose(dpi, 150, abs_tol=1)
    axes_and_legend = fig.legends[0].get_window_extent().x1 / fig.dpi * 150
    assert width >= axes_and_legend - 2  # the legend beside the figure is kept, not cut


def test_the_alt_text_says_which_entry_is_best_and_worst():
    text = ranking(CURVES, [0.1, 0.5, 1.0], "fraction", "lowest error", "highest error", True)
    assert text == (
        "The lowest error: sdnn (acc, torch, cosine) at fractions 0.1 and 1; sdnn (acc, torch, "
        "converge) at fraction 0.5. ffnn (acc, torch, converge) has the highest error at every "
        "fraction."
    )
    bars = ranking(BARS, ["iid", "unseen-heading"], "split", "highest", "lowest", False)
    assert bars == (
        "The highest: sdnn (acc, torch) at split iid; sdnn (acc, jax) at split unseen-heading. "
        "gnn (acc, torch) has the lowest at every split."
    )
    assert ranking(BARS[:1], ["iid"], "split", "highest", "lowest", False) == (
        "Only gnn (acc, torch) is shown."
    )


def test_a_runs_plot_is_drawn_with_its_models_colour(tmp_path):
    """The public `sample_efficiency_png` (the sample-efficiency evaluator's plot of a run):
    a label's model, its text before ' (', fixes the colour."""
    drawn = []
    path = tmp_path / "run.png"
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr("symbench.core.board.plots.write_png", lambda fig, p: drawn.append(fig))
        sample_efficiency_png({"sdgnn (jax)": ([0.5, 1.0], [0.2, 0.1], None)}, "run", path)
    (line,) = (c.lines[0] for c in drawn[0].axes[0].containers)
    assert line.get_color() == colour_of("sdgnn")
    assert list(line.get_ydata()) == [math.log10(0.2), -1.0]  # drawn on a log axis
    sample_efficiency_png({"sdgnn (jax)": ([0.5, 1.0], [0.2, 0.1], None)}, "run", path)
    assert path.read_bytes().startswith(b"\x89PNG")
