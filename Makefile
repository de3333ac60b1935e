VENV ?= .venv
PY := $(VENV)/bin/python
STAMP := $(VENV)/.installed
BENCH_STAMP := $(VENV)/.installed-bench

.PHONY: install demo test test-slow test-all lint types check bench clean

$(STAMP): pyproject.toml
	test -x $(PY) || python3 -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip
	$(PY) -m pip install --quiet -e '.[dev]'
	touch $(STAMP)

$(BENCH_STAMP): $(STAMP)
	$(PY) -m pip install --quiet -e '.[dev,bench]'
	touch $(BENCH_STAMP)

install: $(STAMP)

demo: $(STAMP)
	$(VENV)/bin/taut demo --out report

# pytest-xdist: one worker per core (-n auto); worksteal hands the tail of a worker's queue to
# whichever worker is idle, so that the minute-long tests do not leave a core waiting
XDIST := -n auto --dist worksteal

test: $(STAMP)
	$(PY) -m pytest -q $(XDIST) --durations=20

test-slow: $(STAMP)
	$(PY) -m pytest -q $(XDIST) --durations=20 -m slow

test-all: $(STAMP)
	$(PY) -m pytest -q $(XDIST) --durations=20 -m ''

lint: $(STAMP)
	$(VENV)/bin/ruff check src tests benchmarks
	$(VENV)/bin/ruff format --check src tests benchmarks

types: $(STAMP)
	$(VENV)/bin/mypy

# the quick suite first, so that CI reports its failures before the slow reproductions run
check: lint types test test-slow

bench: $(BENCH_STAMP)
	@for b in benchmarks/bench_*.py; do echo "== $$b"; $(PY) $$b || exit 1; done

clean:
	rm -rf $(VENV) report .pytest_cache
