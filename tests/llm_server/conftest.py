"""One real llama.cpp server (SmolLM2-135M-Instruct, 2 threads) for the whole session."""

from __future__ import annotations

from collections.abc import Iterator

import pytest

from llm_server.llama_server import LlamaServer, LlamaServerUnavailableError, install_llm_server


@pytest.fixture(scope="session")
def llama_server(tmp_path_factory: pytest.TempPathFactory) -> Iterator[LlamaServer]:
    try:
        python = install_llm_server()
    except LlamaServerUnavailableError as exc:
        pytest.fail(f"cannot install the llama.cpp server: {exc}", pytrace=False)
    server = LlamaServer(python, tmp_path_factory.mktemp("llama") / "server.log")
    try:
        server.start()
    except LlamaServerUnavailableError as exc:
        pytest.fail(f"cannot start the llama.cpp server: {exc}", pytrace=False)
    yield server
    server.stop()
