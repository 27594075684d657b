"""The Optuna journal a `symbench tune` search lives in, opened for resuming: a damaged
journal, or one whose finished trials are not what the search writes, is refused in one line
naming the file and saying how to go on, instead of Optuna's exception from its replay (a
JSONDecodeError with no file name, an "internal error" on the command line)."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from symbench.core.common.errors import SymbenchError

PARAMS = ("learning_rate", "width_scale")  # what every trial of the grid asks for
# the user attributes a finished trial holds (`tune.Trial`'s fields), and their types
ATTRS: dict[str, tuple[type, ...]] = {
    "learning_rate": (float,),
    "width_scale": (float,),
    "hyper": (dict,),
    "parameters": (int,),
    "best_val_loss": (float, int),
    "steps": (int,),
    "stopped_by": (str,),
}
# what Optuna's replay of a damaged journal raises: undecodable lines (ValueError, its
# JSONDecodeError and UnicodeDecodeError), and operations missing fields or of another shape
REPLAY_ERRORS = (
    ValueError,
    KeyError,
    TypeError,
    IndexError,
    AttributeError,
    RecursionError,
    AssertionError,  # an operation code Optuna does not know: "Should not reach."
)


def open_study(journal: Path, name: str) -> Any:
    """The study `name` of `journal` (made when missing), every finished trial checked."""
    import optuna
    from optuna.storages import JournalStorage
    from optuna.storages.journal import JournalFileBackend
    from optuna.trial import TrialState

    try:
        storage = JournalStorage(JournalFileBackend(str(journal)))
        study = optuna.create_study(
            study_name=name, storage=storage, direction="minimize", load_if_exists=True
        )
        finished = study.get_trials(deepcopy=False, states=(TrialState.COMPLETE,))
    except REPLAY_ERRORS as error:
        raise _damaged(journal, f"{type(error).__name__}: {error}") from None
    for trial in finished:
        why = _foreign(trial.params, trial.user_attrs)
        if why is not None:
            raise _damaged(journal, f"trial {trial.number} {why}")
    return study


def _foreign(params: dict[str, Any], attrs: dict[str, Any]) -> str | None:
    """Why a finished trial is not one this search wrote (None: it is)."""
    if set(params) != set(PARAMS):
        return f"has parameters {sorted(map(str, params))}, not {list(PARAMS)}"
    if not all(isinstance(params[k], float) for k in PARAMS):
        return f"has parameters {json.dumps(params)[:60]}, not numbers"
    return malformed_trial(attrs)


def malformed_trial(attrs: Any) -> str | None:
    """Why `attrs` are not the fields a finished trial holds (`tune.Trial`'s, ATTRS), each
    of its type (None: they are); the journal's and the summary's check."""
    if not isinstance(attrs, dict):
        return f"has a trial {json.dumps(attrs)[:40]}, not an object"
    for key, types in ATTRS.items():
        value = attrs.get(key)
        if not isinstance(value, types) or isinstance(value, bool):
            return f"has {key} {json.dumps(value)[:40]}, not a {types[0].__name__}"
    hyper = attrs["hyper"]
    if not all(isinstance(v, int) and not isinstance(v, bool) for v in hyper.values()):
        return f"has sizes {json.dumps(hyper)[:60]}, not integers"
    return None


def _damaged(journal: Path, why: str) -> SymbenchError:
    return SymbenchError(
        f"tuning journal {journal} is damaged ({why}); to go on, move it aside and run the "
        "same command again: the search starts afresh (its finished trials are trained again)"
    )
