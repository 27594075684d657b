"""One colour per model on every plot: the palette maps a model's name to its colour (the
built-in models fixed, any other by a hash of its name), no two of its colours are a red and
a green, and the plots of the site and of the Markdown board draw each model in it."""

from __future__ import annotations

import colorsys
import re
from pathlib import Path

from matplotlib.colors import to_hex
from matplotlib.container import BarContainer
from matplotlib.figure import Figure
from site_records import HEXA

from symbench.core.board.leaderboard import aggregate, load_records, write_leaderboard
from symbench.core.board.palette import (
    MODEL_COLOURS,
    OKABE_ITO,
    OTHER_COLOURS,
    colour_of,
    styles_of,
)
from symbench.core.board.site import plots as site_plots
from symbench.core.runs.results import write_record

BUILT_IN = {
    "sdnn": "#0072B2",
    "sdgnn": "#56B4E9",
    "gnn": "#009E73",
    "ffnn": "#E69F00",
    "ffnn-leg": "#CC79A7",
}


def test_the_built_in_models_have_fixed_colours_and_others_a_hashed_one():
    assert {m: colour_of(m) for m in BUILT_IN} == BUILT_IN
    others = [f"plugin-model-{i}" for i in range(20)]
    colours = [colour_of(m) for m in others]
    assert set(colours) == set(OTHER_COLOURS)  # the rest of the palette, both used
    assert [colour_of(m) for m in reversed(others)] == colours[::-1]  # by name, not place
    assert not set(colours) & set(BUILT_IN.values())


def is_red(colour: str) -> bool:
    hue, _, saturation = colorsys.rgb_to_hls(*(int(colour[i : i + 2], 16) / 255 for i in (1, 3, 5)))
    return saturation > 0.4 and (hue < 30 / 360 or hue > 345 / 360)


def is_green(colour: str) -> bool:
    hue, _, saturation = colorsys.rgb_to_hls(*(int(colour[i : i + 2], 16) / 255 for i in (1, 3, 5)))
    return saturation > 0.4 and 75 / 360 <= hue <= 170 / 360


def red_green_pairs(colours: set[str]) -> list[tuple[str, str]]:
    return [(r, g) for r in colours if is_red(r) for g in colours if is_green(g)]


def test_no_two_models_are_a_red_and_a_green():
    palette = set(MODEL_COLOURS.values()) | set(OTHER_COLOURS)
    assert palette <= set(OKABE_ITO.values())
    assert red_green_pairs(palette) == []
    # the check can fail: Okabe-Ito's vermillion beside gnn's bluish green
    assert red_green_pairs(palette | {OKABE_ITO["vermillion"]}) == [
        (OKABE_ITO["vermillion"], OKABE_ITO["bluish green"])
    ]


def test_a_models_entries_differ_in_style_not_colour():
    styles = styles_of(["sdnn", "ffnn", "sdnn", "sdnn"])
    assert styles[0] == styles[1]  # each model's first entry: plain
    assert len({(s.marker, s.linestyle, s.hatch) for s in (styles[0], *styles[2:])}) == 3


def drawn_colours(fig: Figure) -> dict[str, str]:
    """Each legend entry's colour as drawn: a bar's face, or a line's."""
    colours = {}
    for ax in fig.axes:
        for container in ax.containers:
            if isinstance(container, BarContainer):
                colour = container.patches[0].get_facecolor()
            elif container.lines[0] is not None:  # not a bar's error bars
                colour = container.lines[0].get_color()
            else:
                continue
            colours[container.get_label()] = to_hex(colour).upper()
    return colours


def model_of(label: str) -> str:
    return label.split(" (")[0]


def write_page(folder: Path, make_record, robot: str, models: list[str]) -> None:
    """Records of `models` on the splits of all four site plots, the closed loop on iid."""
    splits = ("fraction-0.5", "iid", "unseen-rotation", "unseen-heading")
    for i, model in enumerate(models):
        for split in splits:
            for seed in range(3):
                record = make_record(robot=robot, model=model, split=split, seed=seed)
                record["metrics"]["torque-error"]["rmse"] = 0.1 * (i + 1) + seed / 100
                if split == "iid":
                    record["metrics"]["closed-loop"] = {
                        "pd_normalized_score": 0.5 + seed / 10,
                        "pd_time_to_failure_s": 1.0,
                        "pd_success_rate": 0.5,
                        "pd_joint_rmse_rad": 0.02,
                    }
                write_record(record, folder / f"{robot}-{model}-{split}-{seed}.json")


def test_every_plot_of_every_page_draws_a_model_in_its_colour(tmp_path, make_record, monkeypatch):
    # two pages with models in other orders and sets: a position would give other colours
    write_page(tmp_path / "records", make_record, "hexa", ["sdnn", "gnn", "ffnn", "my-net"])
    write_page(tmp_path / "records", make_record, "nona", ["ffnn", "my-net", "sdgnn"])
    table = aggregate(load_records(tmp_path / "records"))
    figures: list[Figure] = []
    monkeypatch.setattr(site_plots, "write_svg", lambda fig, path: figures.append(fig))
    for robot in ("hexa", "nona"):
        rows = table[table.robot == robot]
        plots = site_plots.draw_plots(rows, robot, rows.dataset.iloc[0], tmp_path / "site")
        assert all(p.path is not None for p in plots)
    assert len(figures) == 8
    seen: dict[str, set[str]] = {}
    for fig in figures:
        for label, colour in drawn_colours(fig).items():
            seen.setdefault(model_of(label), set()).add(colour)
    assert seen == {m: {colour_of(m)} for m in ("sdnn", "gnn", "ffnn", "my-net", "sdgnn")}


def test_the_markdown_board_draws_a_model_in_its_colour(tmp_path, make_record, monkeypatch):
    write_page(tmp_path / "records", make_record, "hexa", ["ffnn-leg", "sdnn"])
    figures: list[Figure] = []
    monkeypatch.setattr(
        "symbench.core.board.leaderboard.write_png", lambda fig, path: figures.append(fig)
    )
    write_leaderboard(tmp_path / "records", tmp_path / "out")
    (fig,) = figures
    assert {model_of(k): v for k, v in drawn_colours(fig).items()} == {
        "ffnn-leg": BUILT_IN["ffnn-leg"],
        "sdnn": BUILT_IN["sdnn"],
    }


def svg_palette_colours(svg: bytes) -> set[str]:
    """The palette's colours (but black, which axes and text use) that an SVG fills or
    strokes with."""
    found = {c.upper() for c in re.findall(rb"(?:fill|stroke): (#[0-9a-f]{6})", svg)}
    palette = {c.encode() for c in OKABE_ITO.values()} - {OKABE_ITO["black"].encode()}
    return {c.decode() for c in found & palette}


def test_the_sites_svgs_hold_the_colours_of_their_models_only(site):
    def drawn(plot: str) -> set[str]:
        return svg_palette_colours((site / "boards" / f"hexa__{HEXA}-{plot}.svg").read_bytes())

    # the sample-efficiency plot has the schema-1 model too (its iid point at 1)
    expected = {colour_of(m) for m in ("sdnn", "gnn", "ffnn")}
    legacy = {colour_of("mlp-legacy")} - {OKABE_ITO["black"]}
    assert drawn("sample-efficiency") == expected | legacy
    assert drawn("closed-loop") == expected
