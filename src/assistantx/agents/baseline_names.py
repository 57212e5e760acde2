"""The names of the paper's LLM baselines, apart from their code: the registry lists every
reasoner by name at import, and the baselines' module (with the LLM agents under it) is
loaded only when one of them is built."""

from __future__ import annotations

from typing import Literal

BaselineName = Literal["direct", "cot", "react", "reflexion", "mobile_agent_v2"]
BASELINES: tuple[BaselineName, ...] = ("direct", "cot", "react", "reflexion", "mobile_agent_v2")
