"""The site's closed-loop plot shows the board's headline: the tracking score where the
records have it (v7), the score of the time held where they do not (v6), as the summary and
the claims do."""

from __future__ import annotations

import pytest
from matplotlib.container import BarContainer
from matplotlib.figure import Figure

from symbench.core.board.leaderboard import aggregate, load_records
from symbench.core.board.site import plots as site_plots
from symbench.core.runs.results import write_record

SCORES = {"sdnn": 0.8, "ffnn": 0.3}


def drawn(folder, make_record, monkeypatch, tracking: bool) -> tuple[site_plots.Plot, Figure]:
    for model, score in SCORES.items():
        for seed in range(3):
            record = make_record(robot="hexa", model=model, split="iid", seed=seed)
            record["metrics"]["closed-loop"] = {
                "pd_normalized_score": 1 - score,  # the opposite order: a wrong pick shows
                "pd_time_to_failure_s": 1.0,
                "pd_success_rate": 0.5,
                "pd_joint_rmse_rad": 0.02,
            }
            if tracking:
                record["metrics"]["closed-loop"]["pd_tracking_score"] = score + seed / 100
            write_record(record, folder / f"{model}-{seed}.json")
    rows = aggregate(load_records(folder))
    figures: list[Figure] = []
    monkeypatch.setattr(site_plots, "write_svg", lambda fig, path: figures.append(fig))
    plot = site_plots.draw_plots(rows, "hexa", rows.dataset.iloc[0], folder / "site")[1]
    (figure,) = figures
    return plot, figure


def bar_heights(figure: Figure) -> dict[str, float]:
    return {
        c.get_label().split(" (")[0]: c.patches[0].get_height()
        for ax in figure.axes
        for c in ax.containers
        if isinstance(c, BarContainer)
    }


@pytest.mark.parametrize("tracking", [True, False])
def test_the_plot_shows_the_tracking_score_where_records_have_it(
    tmp_path, make_record, monkeypatch, tracking
):
    plot, figure = drawn(tmp_path, make_record, monkeypatch, tracking)
    heights = bar_heights(figure)
    if tracking:
        assert "tracking score" in plot.caption
        expected = {m: s + 0.01 for m, s in SCORES.items()}  # the mean over seeds 0-2
    else:
        assert "tracking" not in plot.caption and "closed-loop score" in plot.caption
        expected = {m: 1 - s for m, s in SCORES.items()}
    assert heights == {m: pytest.approx(v, abs=1e-12) for m, v in expected.items()}
