"""Simulating a preset's scenario grid into a dataset, on pinned numerics, and knowing
whether a cached dataset is the standard one (its reference content hash)."""
