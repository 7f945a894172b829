# SARTCo bench: the two commands of the README are `make main` and `make test`.
PYTHON ?= python3
VENV   ?= .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed
RESULTS ?= results
## The versions a working install used (constraints.txt: what decides a score or runs a model, and
## what they need); `make install CONSTRAINTS=` installs the newest that pyproject.toml allows.
CONSTRAINTS ?= constraints.txt

.PHONY: install main test lint local upgrade-check clean-results

$(STAMP): pyproject.toml setup.py $(CONSTRAINTS)
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install -q --upgrade pip
	$(BIN)/python -m pip install -q $(if $(CONSTRAINTS),-c $(CONSTRAINTS)) -e ".[dev]"
	touch $(STAMP)

install: $(STAMP)

## Newer versions than constraints.txt pins, in a venv of their own (.venv-upgrade): the packages
## that would change ("> name==version"), then whether a recorded score moves with them.
upgrade-check:
	rm -rf .venv-upgrade && $(PYTHON) -m venv .venv-upgrade
	.venv-upgrade/bin/python -m pip install -q --upgrade pip
	.venv-upgrade/bin/python -m pip install -q -e ".[dev]"
	.venv-upgrade/bin/python -m pip freeze --exclude-editable | grep -vxFf constraints.txt || true
	.venv-upgrade/bin/python -m pytest -p no:cacheprovider tests/scores/test_pinned_scores.py

## The main job: both games with the built-in players over the test split, scored, transcribed,
## evaluated and reported; ends by printing the results table.
main: $(STAMP)
	PATH="$(abspath $(BIN)):$$PATH" RESULTS="$(RESULTS)" bash scripts/main.sh

## Unit, property and end-to-end tests.
test: $(STAMP)
	$(BIN)/python -m pytest

## ruff with the rules of pyproject.toml ([tool.ruff]); CI runs it before the tests.
lint: $(STAMP)
	$(BIN)/ruff check .

## A real small model (Gemma 3 270M on a local llama.cpp server) over a slice of both games.
local: $(STAMP)
	PATH="$(abspath $(BIN)):$$PATH" CONSTRAINTS="$(CONSTRAINTS)" bash scripts/local_model.sh

clean-results:
	rm -rf $(RESULTS)
