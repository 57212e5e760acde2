"""One real llama.cpp server (SmolLM2-135M-Instruct, 2 threads) for the whole session, and
its speed, measured once, from which every test sizes its budgets."""

from __future__ import annotations

import asyncio
from collections.abc import Iterator

import pytest

from llm_server.llama_server import (
    MODEL_NAME,
    LlamaServer,
    LlamaServerUnavailableError,
    install_llm_server,
)
from llm_server.speed import ServerSpeed, measure


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


@pytest.fixture(scope="session")
def server_speed(llama_server: LlamaServer) -> ServerSpeed:
    speed = asyncio.run(measure(llama_server.base_url, MODEL_NAME))
    print(f"\nllama.cpp server: {speed.prompt_tps:.0f} prompt tok/s, "
          f"{speed.generate_tps:.1f} completion tok/s")  # fmt: skip
    return speed
