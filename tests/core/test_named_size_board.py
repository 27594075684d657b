"""Build keywords set by name (`--size mirror=1`): named in the run key and the record since
2026-12-06, ranked in sections of their own on the board; records made before keep their
seals and keys."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

from symbench.core.board.leaderboard import aggregate, load_records, markdown
from symbench.core.board.site.reproduce import run_command
from symbench.core.board.sizes import size_of, size_order
from symbench.core.board.summary import headline
from symbench.core.runs.results import read_record, run_key, write_record
from symbench.core.runs.verify import replay_spec

# made with --size mirror=1 before the key named it
MIRROR_STUDY = Path(__file__).resolve().parents[2] / "leaderboards/studies/mirror-group-v7/records"
ARGS = ("hexa-climb-small-v7", "small", "iid", "sdnn", "acc", "torch", "converge", 0)
DEFAULT_KEY = "hexa-climb-small-v7__small__iid__sdnn__acc__torch__converge__seed0"


def named(record: dict, **sizes: int) -> dict:
    record["model"]["sizes"] = sizes
    record["model"]["hyperparameters"].update(sizes)
    record["training"]["config"]["hyper"] = dict(sizes)
    return record


def test_key_names_each_keyword_by_name_after_a_matched_size():
    assert run_key(*ARGS, sizes={}) == DEFAULT_KEY
    assert run_key(*ARGS, sizes={"ring": 1, "mirror": 1}) == DEFAULT_KEY.replace(
        "__seed0", "__mirror-1__ring-1__seed0"
    )
    assert run_key(*ARGS, 100000, {"mirror": 1}).endswith("__p100000__mirror-1__seed0")
    # a keyword named p cannot pass for a matched size
    assert run_key(*ARGS, sizes={"p": 100000}) != run_key(*ARGS, 100000)


def test_spec_record_and_replay_agree(tmp_path, make_record):
    record = write_record(named(make_record(), mirror=1), tmp_path / "r.json")
    spec = replay_spec(record, tmp_path, 1)  # verify's run: its key from its own sizes
    assert spec.sizes == (("mirror", 1),)
    assert record.key() == spec.key() and record.key().endswith("__mirror-1__seed0")
    assert replace(spec, sizes=()).key() == record.key().replace("__mirror-1", "")
    assert run_command(record).endswith(" --size mirror=1")
    assert "sizes" not in write_record(make_record(), tmp_path / "d.json").model_dump_json()


def test_records_made_before_the_field_keep_their_seals_and_keys():
    records = sorted(MIRROR_STUDY.glob("*.json"))
    assert len(records) == 40
    for path in records:
        record = read_record(path)  # the seal is checked
        assert record.training.config.hyper == {"mirror": 1} and record.model.sizes is None
        assert record.key() == path.stem and size_of(record) == "default"


def test_a_named_size_ranks_in_its_own_section(tmp_path, make_record):
    """Plain sdnn ahead of ffnn; mirror sdnn alone in its section, ranked 1 there although
    its error is the largest."""
    for seed in range(3):
        for model, rmse, sizes in (
            ("sdnn", 0.2, {}),
            ("ffnn", 0.5, {}),
            ("sdnn", 0.9, {"mirror": 1}),
        ):
            record = make_record(model=model, seed=seed, rmse=rmse + seed / 100)
            sealed = write_record(named(record, **sizes) if sizes else record, tmp_path / "x")
            write_record(sealed, tmp_path / f"{sealed.key()}.json")
    (tmp_path / "x").unlink()
    assert len(list(tmp_path.glob("*.json"))) == 9  # one folder, no shared key
    table = aggregate(load_records(tmp_path))
    ranks = {(r["size"], r.model): r["rank"] for _, r in table.iterrows()}
    assert ranks == {("default", "sdnn"): 1, ("default", "ffnn"): 2, ("with mirror=1", "sdnn"): 1}
    page = markdown(table, "hexa")
    default, mirror = page.split(", built with mirror=1")
    assert "0.91" not in default and "0.91" in mirror
    assert "# Trained under the paper protocol, built with mirror=1" in headline(table)
    assert sorted(["with mirror=1", "matched 100000", "default"], key=size_order) == [
        "default",
        "matched 100000",
        "with mirror=1",
    ]


def test_the_command_of_a_record_on_an_earlier_dataset_version_keeps_its_budget(
    tmp_path, make_record
):
    """A `small@v6` record names its preset and, where its budget was not the preset's, the
    budget (it was left out: the earlier version's presets were not looked up)."""
    record = make_record()
    record["dataset"] |= {"id": "hexa-climb-smoke-v6", "preset": "smoke@v6"}
    record["training"]["config"]["max_epochs"] = 7  # smoke@v6's cap is 3
    command = run_command(write_record(record, tmp_path / "r.json"))
    assert " --preset smoke@v6 " in command and command.endswith(" --max-epochs 7")
