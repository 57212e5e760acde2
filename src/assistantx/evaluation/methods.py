"""The methods the harness compares, each turned into a reasoner factory for one task.

``optimal`` (the upper bound: the dataset's optimal policy, needs the task's ``spec``),
``ppdr`` (the loop with the chosen reasoner), its ablations, and the LLM baselines. The
reasoners themselves come from the one registry (:mod:`assistantx.agents.registry`); what is
the harness's own is the method names (``ppdr`` is the chosen PPDR reasoner), their labels in
reports, and giving the optimal policy each task.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from assistantx.agents.ablations import ABLATIONS
from assistantx.agents.base import ReasonerFactory
from assistantx.agents.baseline_names import BASELINES
from assistantx.agents.registry import (
    ORACLE,
    OracleTask,
    needs_llm,
    reasoner_factory,
)
from assistantx.core.errors import ReasonerError
from assistantx.core.office import Office
from assistantx.core.ports.model import ChatModel
from assistantx.core.settings import Settings
from assistantx.evaluation.dataset.tasks import Task

METHODS: tuple[str, ...] = (ORACLE, "ppdr", *ABLATIONS, *BASELINES)

# The chat model the settings name (None: no model configured); given by the composition root
# (the CLI passes ``assistantx.adapters.model.model_from_settings``), so that the harness's
# worker processes build their own client.
ModelBuilder = Callable[[Settings], ChatModel | None]


@dataclass(frozen=True)
class MethodSpec:
    method: str
    reasoner: str = "symbolic"  # for ppdr and its ablations

    @property
    def label(self) -> str:
        if self.method == "ppdr" or self.method in ABLATIONS:
            return f"{self.method} ({self.reasoner})"
        return self.method

    @property
    def registry_name(self) -> str:
        """The reasoner's name in the registry: ``ppdr`` is the chosen PPDR reasoner."""
        return self.reasoner if self.method == "ppdr" else self.method

    @property
    def needs_llm(self) -> bool:
        return needs_llm(self.registry_name, inner=self.reasoner)


class MethodBuilder:
    """Builds reasoner factories for one method; expensive parts (prompts, the parser) once.
    The LLM methods get their ``model`` from the caller (the CLI or a bench script builds it)."""

    def __init__(
        self,
        spec: MethodSpec,
        office: Office,
        settings: Settings,
        *,
        build_model: ModelBuilder | None = None,
    ) -> None:
        if spec.method not in METHODS:
            raise ReasonerError(f"unknown method {spec.method!r}; choose from {', '.join(METHODS)}")
        self.spec = spec
        self.office = office
        self.settings = settings
        self._shared: ReasonerFactory | None = None
        model = build_model(settings) if build_model is not None and spec.needs_llm else None
        if spec.method != ORACLE:  # the optimal policy is made per task, knowing the task
            self._shared = reasoner_factory(
                spec.registry_name, office, settings, inner=spec.reasoner, model=model
            )

    def factory(self, task: Task) -> ReasonerFactory:
        if self._shared is not None:
            return self._shared
        oracle = OracleTask(task.id, task.requester, task.instruction, task.spec)
        return reasoner_factory(ORACLE, self.office, self.settings, task=oracle)


METRICS_HELP = (
    "Methods: optimal (the dataset's optimal policy, an upper bound), ppdr with --reasoner "
    "symbolic|llm, its ablations ppdr-no-perception/-planning/-reflection, and the LLM "
    "baselines direct, cot, react, reflexion, mobile_agent_v2 (need ASSISTANTX_LLM_BASE_URL)."
)
