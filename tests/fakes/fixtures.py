"""Pytest fixtures other test folders import into their ``conftest.py``::

from fakes.fixtures import scripted_llm  # noqa: F401
"""

from __future__ import annotations

from collections.abc import AsyncIterator
from typing import TYPE_CHECKING

import pytest

if TYPE_CHECKING:
    from fakes.scripted_llm import ScriptedLLM


@pytest.fixture
async def scripted_llm() -> AsyncIterator[ScriptedLLM]:
    """A scripted OpenAI-compatible server on 127.0.0.1, stopped after the test."""
    # Imported here: tests/conftest.py imports this module in every process, xdist's
    # controller too, which runs no test (FastAPI and uvicorn: ~1 CPU-s there).
    from fakes.scripted_llm import ScriptedLLM

    async with ScriptedLLM() as server:
        yield server
