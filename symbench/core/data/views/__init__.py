"""Raw trajectories to model inputs: the three views' feature schemas, leg frames and
the vectorised transforms."""
