"""Pytest fixtures other test folders import into their ``conftest.py``::

from fakes.fixtures import scripted_llm  # noqa: F401
"""

from __future__ import annotations

from collections.abc import AsyncIterator

import pytest

from fakes.scripted_llm import ScriptedLLM


@pytest.fixture
async def scripted_llm() -> AsyncIterator[ScriptedLLM]:
    """A scripted OpenAI-compatible server on 127.0.0.1, stopped after the test."""
    async with ScriptedLLM() as server:
        yield server
