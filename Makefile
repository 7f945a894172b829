# SARTCo bench: the two commands of the README are `make main` and `make test`.
PYTHON ?= python3
VENV   ?= .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed
RESULTS ?= results
## The versions a working install used (constraints.txt: what decides a score or runs a model, and
## what they need); `make install CONSTRAINTS=` installs the newest that pyproject.toml allows.
CONSTRAINTS ?= constraints.txt

.PHONY: install main test test-py312 test-train lint local upgrade-check clean-results

## The Pythons it installs on: pyproject.toml's requires-python (">=3.11,<3.13"), read here, so that
## another interpreter stops with one line before pip fails to find clemcore.
PY_MIN := $(shell sed -n 's/^requires-python = ">=3\.\([0-9]*\),<3\.[0-9]*"/\1/p' pyproject.toml)
PY_END := $(shell sed -n 's/^requires-python = ">=3\.[0-9]*,<3\.\([0-9]*\)"/\1/p' pyproject.toml)

$(STAMP): pyproject.toml setup.py $(CONSTRAINTS)
	@v=$$($(PYTHON) -c 'import sys; print("%d.%d" % sys.version_info[:2])' 2>/dev/null); m=$${v#3.}; \
	  case "$$v" in 3.*) [ "$$m" -ge $(PY_MIN) ] && [ "$$m" -lt $(PY_END) ] && exit 0;; esac; \
	  echo "make install: $(PYTHON) is Python $${v:-unknown}; sartco-bench installs on Python 3.$(PY_MIN) to 3.$$(($(PY_END) - 1)) only (pyproject.toml's requires-python: clemcore 3.7, which it runs on, declares <3.$(PY_END) in every release); give one: make install PYTHON=python3.$(PY_MIN)" >&2; exit 2
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install -q --upgrade pip
	$(BIN)/python -m pip install -q $(if $(CONSTRAINTS),-c $(CONSTRAINTS)) -e ".[dev,ray]"
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

## Unit, property and end-to-end tests, on every core (pytest-xdist): each test file on one worker,
## the longest files first (tests/conftest.py); ends with the 15 slowest tests. One worker more
## than cores: a fifth of the tests' time is spent waiting (servers' latency and timeouts, a child
## process), and the extra worker fills it (docs/testing.md).
TEST_WORKERS ?= $(shell expr $$(nproc) + 1)
test: $(STAMP)
	$(BIN)/python -m pytest -n $(TEST_WORKERS) --dist loadfile --no-loadscope-reorder --durations=15

## The sandbox's tests (tests/program) on Python 3.12 too, in a venv of its own (.venv-py312, the
## dev extra, constraints.txt), so that a program gets the same verdict on every interpreter the
## project supports; CI runs it after `make test` (about 4 min on 2 cores, 3 more to install).
## PY312: pyenv's 3.12 on these machines (root's in CI), else python3.12 on the PATH.
PY312 ?= $(firstword $(wildcard $(HOME)/.pyenv/versions/3.12*/bin/python3.12 /root/.pyenv/versions/3.12*/bin/python3.12) \
                     $(shell command -v python3.12 2>/dev/null))
VENV312 := .venv-py312
STAMP312 := $(VENV312)/.installed
$(STAMP312): pyproject.toml setup.py $(CONSTRAINTS)
	@test -n "$(PY312)" || { echo "test-py312 needs Python 3.12 (pyenv install 3.12, or PY312=...)" >&2; exit 2; }
	test -x $(VENV312)/bin/python || $(PY312) -m venv $(VENV312)
	$(VENV312)/bin/python -m pip install -q --upgrade pip
	$(VENV312)/bin/python -m pip install -q $(if $(CONSTRAINTS),-c $(CONSTRAINTS)) -e ".[dev]"
	touch $(STAMP312)

test-py312: $(STAMP312)
	$(VENV312)/bin/python -c 'import sys; assert sys.version_info[:2] == (3, 12), sys.version'
	SARTCO_REQUIRE_RAY= $(VENV312)/bin/python -m pytest -n auto --dist loadfile tests/program

## The trainers' interfaces against the real libraries: one GRPO step of a tiny model on CPU, verl's
## reward managers, a verifiers environment, OpenRLHF's reward client (the `train` extra: torch's CPU
## build, trl, verl, verifiers; see the README for its size). OpenRLHF without its dependencies: it
## requires flash-attn (built only with CUDA), deepspeed and vLLM, which its reward client never imports.
TRAIN_STAMP := $(VENV)/.installed-train
OPENRLHF := openrlhf==0.11.2
$(TRAIN_STAMP): $(STAMP)
	$(BIN)/python -m pip install -q -e ".[dev,train]"
	$(BIN)/python -m pip install -q --no-deps $(OPENRLHF)
	touch $(TRAIN_STAMP)

test-train: $(TRAIN_STAMP)
	SARTCO_REQUIRE_TRAIN=1 $(BIN)/python -m pytest -m train tests/reward/test_trainers.py

## ruff with the rules of pyproject.toml ([tool.ruff]), then mypy ([tool.mypy]) against
## scripts/mypy-baseline.txt (scripts/typecheck.py); CI runs both before the tests.
lint: $(STAMP)
	$(BIN)/ruff check .
	$(BIN)/python scripts/typecheck.py

## A real small model (Gemma 3 270M on a local llama.cpp server) over a slice of both games.
local: $(STAMP)
	PATH="$(abspath $(BIN)):$$PATH" CONSTRAINTS="$(CONSTRAINTS)" bash scripts/local_model.sh

clean-results:
	rm -rf $(RESULTS)
