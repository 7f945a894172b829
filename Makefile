# SARTCo bench: the two commands of the README are `make main` and `make test`.
PYTHON ?= python3
VENV   ?= .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed
RESULTS ?= results

.PHONY: install main test lint local clean-results

$(STAMP): pyproject.toml setup.py
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install -q --upgrade pip
	$(BIN)/python -m pip install -q -e ".[dev]"
	touch $(STAMP)

install: $(STAMP)

## The main job: both games with the built-in players over the test split, scored, transcribed,
## evaluated and reported; ends by printing the results table.
main: $(STAMP)
	PATH="$(abspath $(BIN)):$$PATH" RESULTS="$(RESULTS)" bash scripts/main.sh

## Unit, property and end-to-end tests, on every core (pytest-xdist): each test file on one worker,
## the longest files first (tests/conftest.py); ends with the 15 slowest tests.
test: $(STAMP)
	$(BIN)/python -m pytest -n auto --dist loadfile --no-loadscope-reorder --durations=15

## ruff with the rules of pyproject.toml ([tool.ruff]); CI runs it before the tests.
lint: $(STAMP)
	$(BIN)/ruff check .

## A real small model (Gemma 3 270M on a local llama.cpp server) over a slice of both games.
local: $(STAMP)
	PATH="$(abspath $(BIN)):$$PATH" bash scripts/local_model.sh

clean-results:
	rm -rf $(RESULTS)
