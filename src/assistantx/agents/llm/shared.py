"""One chat model shared by every instruction's reasoner, and the model the settings name.

A reasoner factory makes one reasoner per instruction; they all talk to the same model, so
the model's connection is opened by the first reasoner to start and closed by the last to stop.
"""

from __future__ import annotations

import asyncio

from assistantx.adapters.model import ChatModel, OpenAICompatibleModel
from assistantx.core.errors import ReasonerError
from assistantx.core.settings import Settings


class SharedModel:
    """One chat model used by many reasoners: opened by the first user, closed by the last."""

    def __init__(self, model: ChatModel) -> None:
        self.model = model
        self._users = 0
        self._lock = asyncio.Lock()

    @property
    def users(self) -> int:
        return self._users

    async def acquire(self) -> None:
        async with self._lock:
            if self._users == 0:
                await self.model.start()
            self._users += 1

    async def release(self) -> None:
        async with self._lock:
            if self._users == 0:
                return
            self._users -= 1
            if self._users == 0:
                await self.model.stop()


def model_from_settings(settings: Settings, reasoner: str) -> ChatModel:
    """The OpenAI-compatible client of the settings; ReasonerError, naming ``reasoner``, when
    ``ASSISTANTX_LLM_BASE_URL`` is unset or unusable."""
    if not settings.llm_base_url:
        raise ReasonerError(
            f"the {reasoner} reasoner needs ASSISTANTX_LLM_BASE_URL (an OpenAI-compatible /v1 URL)"
        )
    try:
        return OpenAICompatibleModel.from_settings(settings)
    except ValueError as exc:
        raise ReasonerError(f"cannot use the LLM at {settings.llm_base_url}: {exc}") from exc
