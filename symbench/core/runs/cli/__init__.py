"""The run-layer commands, one module each: run, sweep, tune, verify."""
