"""The chat model the settings name: what a composition root (service, CLI, bench) injects
into the reasoners, which never build a provider themselves."""

from __future__ import annotations

from assistantx.core.errors import ReasonerError
from assistantx.core.ports.model import ChatModel
from assistantx.core.settings import Settings


def model_from_settings(settings: Settings) -> ChatModel | None:
    """The OpenAI-compatible client of ``ASSISTANTX_LLM_BASE_URL``; None when it is unset
    (the reasoners that need a model then say so); ReasonerError when it is unusable."""
    if not settings.llm_base_url:
        return None
    from assistantx.adapters.model.openai_compat import OpenAICompatibleModel  # httpx: here

    try:
        return OpenAICompatibleModel.from_settings(settings)
    except ValueError as exc:
        raise ReasonerError(f"cannot use the LLM at {settings.llm_base_url}: {exc}") from exc
