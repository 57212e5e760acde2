"""One chat model shared by every instruction's reasoner.

A reasoner factory makes one reasoner per instruction; they all talk to the same model, so
the model's connection is opened by the first reasoner to start and closed by the last to stop.
"""

from __future__ import annotations

import asyncio

from assistantx.core.errors import ReasonerError
from assistantx.core.ports.model import ChatModel


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


class ModelHold:
    """One reasoner's hold on a shared model, from its start to its stop: taken once however
    often it starts, given back once however often it stops."""

    def __init__(self, shared: SharedModel) -> None:
        self.shared = shared
        self._holding = False

    async def take(self) -> None:
        if not self._holding:
            await self.shared.acquire()
            self._holding = True

    async def give_back(self) -> None:
        if self._holding:
            self._holding = False
            await self.shared.release()


def require_model(model: ChatModel | None, reasoner: str) -> ChatModel:
    """``model``, injected by the composition root; ReasonerError, naming ``reasoner``, when
    none was (``ASSISTANTX_LLM_BASE_URL`` unset)."""
    if model is None:
        raise ReasonerError(
            f"the {reasoner} reasoner needs a language model: set ASSISTANTX_LLM_BASE_URL "
            "(an OpenAI-compatible /v1 URL) and ASSISTANTX_LLM_MODEL"
        )
    return model
