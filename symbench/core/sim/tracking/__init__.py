"""Learned models as controllers: the reference climbs, the tracking loop, and its video."""
