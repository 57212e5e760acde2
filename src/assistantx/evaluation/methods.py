"""The methods the harness compares, each turned into a reasoner factory for one task.

``optimal`` (the upper bound: the dataset's optimal policy, needs the task's ``spec``),
``ppdr`` (the loop with the chosen reasoner), its ablations, and the LLM baselines.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from assistantx.agents.ablations import ABLATIONS
from assistantx.agents.base import Reasoner
from assistantx.agents.baselines import BASELINES, build_baseline_factory
from assistantx.agents.oracle.optimal import OptimalReasoner
from assistantx.agents.registry import reasoner_factory
from assistantx.core.errors import ReasonerError
from assistantx.core.office import Office
from assistantx.core.settings import Settings
from assistantx.evaluation.dataset.tasks import Task

METHODS: tuple[str, ...] = ("optimal", "ppdr", *ABLATIONS, *BASELINES)

ReasonerFactory = Callable[[], Reasoner]


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
    def needs_llm(self) -> bool:
        return self.method in BASELINES or (
            self.reasoner in ("llm", "hybrid") and self.method not in ("optimal",)
        )


class MethodBuilder:
    """Builds reasoner factories for one method; expensive parts (models, prompts) once."""

    def __init__(self, spec: MethodSpec, office: Office, settings: Settings) -> None:
        if spec.method not in METHODS:
            raise ReasonerError(f"unknown method {spec.method!r}; choose from {', '.join(METHODS)}")
        self.spec = spec
        self.office = office
        self._shared: ReasonerFactory | None = None
        if spec.method in BASELINES:
            self._shared = build_baseline_factory(spec.method, settings)
        elif spec.method != "optimal":
            try:
                self._shared = reasoner_factory(spec.reasoner, office, settings)
            except (ImportError, AttributeError) as exc:
                raise ReasonerError(
                    f"the {spec.reasoner} reasoner is not available: {exc}"
                ) from exc

    def factory(self, task: Task) -> ReasonerFactory:
        if self.spec.method == "optimal":
            office = self.office

            def optimal() -> Reasoner:
                return OptimalReasoner.for_task(
                    office, task.id, task.requester, task.instruction, task.spec
                )

            return optimal
        shared = self._shared
        assert shared is not None
        wrapper = ABLATIONS.get(self.spec.method)
        if wrapper is None:
            return shared

        def ablated() -> Reasoner:
            return wrapper(shared())

        return ablated


METRICS_HELP = (
    "Methods: optimal (the dataset's optimal policy, an upper bound), ppdr with --reasoner "
    "symbolic|llm, its ablations ppdr-no-perception/-planning/-reflection, and the LLM "
    "baselines direct, cot, react, reflexion, mobile_agent_v2 (need ASSISTANTX_LLM_BASE_URL)."
)
