"""The climbing loop: rollouts into raw columns, the compiled loop, and the C functions
it calls."""
