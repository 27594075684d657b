"""The environment that turns numpy's AVX-512 kernels off: numpy's float64 log, log10, exp and
power run on them where the CPU has them; without them, the code every other CPU runs. Tests
of what must be the same bytes on every CPU run a process with it and compare."""

WITHOUT_AVX512 = {"NPY_DISABLE_CPU_FEATURES": "X86_V4 AVX512_ICL AVX512_SPR"}
