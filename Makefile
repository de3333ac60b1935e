VENV ?= .venv
PY := $(VENV)/bin/python
STAMP := $(VENV)/.installed
BENCH_STAMP := $(VENV)/.installed-bench
BROWSER_STAMP := $(VENV)/.installed-browser

.PHONY: install demo test test-slow test-all test-browser chromium lint types check bench clean

$(STAMP): pyproject.toml
	test -x $(PY) || python3 -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip
	$(PY) -m pip install --quiet -e '.[dev]'
	touch $(STAMP)

$(BENCH_STAMP): $(STAMP)
	$(PY) -m pip install --quiet -e '.[dev,bench]'
	touch $(BENCH_STAMP)

$(BROWSER_STAMP): $(STAMP)
	$(PY) -m pip install --quiet -e '.[dev,browser]'
	touch $(BROWSER_STAMP)

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

# Debian's Chromium (playwright's own browser download is not used): installed when missing
# and the machine allows it; where it cannot be, the browser tests skip and say why
CHROMIUM_NAMES := chromium chromium-browser google-chrome google-chrome-stable
chromium:
	@for c in $(CHROMIUM_NAMES); do command -v $$c >/dev/null 2>&1 && exit 0; done; \
	if [ "$$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then \
		(apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq chromium) \
			|| echo "make chromium: apt-get could not install chromium; the browser tests will skip"; \
	elif command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null && command -v apt-get >/dev/null 2>&1; then \
		(sudo apt-get update -qq && sudo DEBIAN_FRONTEND=noninteractive apt-get install -y -qq chromium) \
			|| echo "make chromium: apt-get could not install chromium; the browser tests will skip"; \
	else \
		echo "make chromium: no chromium and no way to install it here (root and apt-get); the browser tests will skip"; \
	fi

# the pages taut writes, in headless Chromium (tests/browser, marker browser): one process,
# one browser; -rs prints why a test skipped
test-browser: $(BROWSER_STAMP) chromium
	$(PY) -m pytest -q -m browser -rs -s -p no:xdist tests/browser

lint: $(STAMP)
	$(VENV)/bin/ruff check src tests benchmarks
	$(VENV)/bin/ruff format --check src tests benchmarks

types: $(STAMP)
	$(VENV)/bin/mypy

# the quick suite first, so that CI reports its failures before the slow reproductions run
check: lint types test test-slow test-browser

bench: $(BENCH_STAMP)
	@for b in benchmarks/bench_*.py; do echo "== $$b"; $(PY) $$b || exit 1; done

clean:
	rm -rf $(VENV) report .pytest_cache
