"""`python -m symbench ...`: the `symbench` command, for an environment whose scripts folder
is not on PATH (or to pick the interpreter explicitly)."""

from symbench.core.cli import main

if __name__ == "__main__":
    main()
