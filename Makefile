# Every target creates the virtual environment when it is missing or stale, so a fresh
# machine needs nothing but Python 3.11 and make.
PYTHON ?= python3.11
VENV := .venv
STAMP := $(VENV)/.installed
export MUJOCO_GL ?= disable

.PHONY: run test test-slow check bench screenshots clean

$(STAMP): pyproject.toml constraints.txt examples/symbench-example-plugin/pyproject.toml \
		examples/symbench-e2cnn/pyproject.toml
	test -x $(VENV)/bin/python || $(PYTHON) -m venv $(VENV)
	$(VENV)/bin/python -m pip install --quiet -c constraints.txt -e '.[test]' -e examples/symbench-example-plugin \
		-e examples/symbench-e2cnn
	touch $(STAMP)

run: $(STAMP)
	$(VENV)/bin/symbench run --model sdnn --robot hexa

# The checks first (seconds): style, format, types, and the layers of the data flow.
check: $(STAMP)
	$(VENV)/bin/ruff check .
	$(VENV)/bin/ruff format --check .
	$(VENV)/bin/mypy
	$(VENV)/bin/lint-imports

test: check
	$(VENV)/bin/python -m pytest -q -n 2

test-slow: $(STAMP)
	$(VENV)/bin/python -m pytest -q -n 2 -m slow

bench: $(STAMP)
	$(VENV)/bin/symbench bench sim --robot hexa
	$(VENV)/bin/symbench bench models

# The docs' screenshots of the committed site (needs Debian's chromium)
screenshots: $(STAMP)
	$(VENV)/bin/python docs/images/take_screenshots.py

clean:
	rm -rf $(VENV)
