"""Contact with the climbing surface: per-step compiled arithmetic and when a climb
has failed."""
