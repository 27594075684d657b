"""The climbing gait: the plan (Python) beside its per-step compiled kernel."""
