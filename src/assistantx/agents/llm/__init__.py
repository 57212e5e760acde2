"""The LLM agents: perception, planning, decision and reflection as prompts to a chat model.

- :mod:`.reasoner`: the four agents (:class:`LLMReasoner`), their prompt set and factory;
- :mod:`.model_reasoner`: one structured, accounted call to the model per agent;
- :mod:`.checks`: the model's outputs checked against memory (names become ids);
- :mod:`.inputs`: what the prompts carry besides memory;
- :mod:`.shared`: one chat model shared by every instruction's reasoner;
- :mod:`.prompts`: the template files.
"""

from assistantx.agents.llm.checks import check_actions, focus_ids, ground_updates
from assistantx.agents.llm.inputs import schema_text
from assistantx.agents.llm.model_reasoner import (
    ModelReasoner,
    agent_call,
    failed_call,
    interrupted_call,
)
from assistantx.agents.llm.reasoner import (
    AGENTS,
    AgentPrompts,
    LLMReasoner,
    LLMReasonerFactory,
    build_factory,
)
from assistantx.agents.llm.shared import SharedModel, require_model

__all__ = [
    "AGENTS",
    "AgentPrompts",
    "LLMReasoner",
    "LLMReasonerFactory",
    "ModelReasoner",
    "SharedModel",
    "agent_call",
    "build_factory",
    "check_actions",
    "failed_call",
    "focus_ids",
    "ground_updates",
    "interrupted_call",
    "require_model",
    "schema_text",
]
