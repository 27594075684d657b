"""The image-overlap evaluator keeps the split's own overlap figures in every record: whether
the test climbs are new to the model or images of its training climbs."""

from __future__ import annotations

from types import SimpleNamespace

from symbench.core.runs.overlap_cache import cached_split_overlap
from symbench.plugins.evaluators import image_overlap

# smoke's grid on hexa: yaws 0 and 180 (an image under C6) at headings 0 and 180 (images
# under the heading) are one motion up to the group; yaw 250 (10 degrees off every rotated
# image of 0) at both headings is the other
_MOTION = {0.0: "a", 180.0: "a", 250.0: "b"}


def test_the_record_says_which_test_climbs_are_images_of_training_climbs(
    simulated_smoke_hexa, tmp_path
):
    dataset = simulated_smoke_hexa
    context = SimpleNamespace(
        image_overlap=lambda: cached_split_overlap(dataset, "iid", 0, tmp_path)
    )
    out = image_overlap.evaluate(context)
    parts = dataset.split_indices("iid", 0)
    yaw = {i: s["yaw_deg"] for i, s in zip(dataset.trajectory_ids, dataset.scenarios)}
    trained = {_MOTION[yaw[int(i)]] for i in parts.train}
    expected = sum(_MOTION[yaw[int(i)]] in trained for i in parts.test) / len(parts.test)
    assert out["test_climbs"] == len(parts.test) and out["train_climbs"] == len(parts.train)
    assert out["test_group_exact_image_share"] == expected
    assert out["test_mirror_exact_image_share"] >= expected  # a wider class finds no fewer
    assert out["test_none_exact_image_share"] == 0  # no climb repeats another as recorded
    assert out["train_group_motions"] == len(trained)


def test_it_is_a_registered_evaluator_of_every_run():
    from symbench.core.plugin import registry
    from symbench.core.runs.spec import DEFAULT_EVALUATORS, FIRST_RESULT_EVALUATORS

    entry = registry.evaluator("image-overlap")
    assert entry.needs == ("raw",) and "symmetry class" in entry.description
    assert "image-overlap" in DEFAULT_EVALUATORS and "image-overlap" in FIRST_RESULT_EVALUATORS
