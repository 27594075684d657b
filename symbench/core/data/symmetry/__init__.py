"""A robot's symmetry acting on raw states, and how symmetric a dataset is (image
pairs compared after relabelling)."""
