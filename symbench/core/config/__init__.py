"""What a run is configured with and what it records: presets (sizes, budgets, horizons),
training protocols, provenance. Below data, training and runs, so every layer reads one copy."""
