"""Every reasoner by name: the one place that turns a name into a reasoner factory.

``serve``, ``run``, ``eval`` and the tests all build reasoners here:

- the PPDR reasoners ``symbolic`` (embedded, the default without an LLM), ``llm`` (the four
  LLM agents), ``hybrid`` (the model reads the request, the symbolic PPDR carries it out)
  and ``cascade`` (the hybrid that asks the model only when the embedded reader is unsure);
- the ablations ``ppdr-no-perception``, ``ppdr-no-planning``, ``ppdr-no-reflection``, each
  wrapping a PPDR reasoner (``inner``, symbolic unless told);
- the paper's LLM baselines ``direct``, ``cot``, ``react``, ``reflexion``,
  ``mobile_agent_v2``;
- ``optimal``, the dataset's optimal policy, which must be told the task (``task``);
- and a plugin, ``"module:builder"`` (:func:`load_builder`), for ``ASSISTANTX_REASONER_BUILDER``.

A factory makes one reasoner per instruction; what is expensive (loaded prompts, the
instruction parser) is built once, when the factory is. The chat model of the LLM reasoners is
injected (``model``): the composition root (service, CLI, bench) builds the provider, the
agents never import one. The PPDR reasoners are
imported lazily, so that the CLI starts fast and a missing optional part names itself.
"""

from __future__ import annotations

import importlib
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any, Literal

from assistantx.agents.ablations import ABLATIONS
from assistantx.agents.base import Reasoner, ReasonerFactory
from assistantx.agents.baseline_names import BASELINES
from assistantx.core.errors import ReasonerError
from assistantx.core.office import Office
from assistantx.core.ports.model import ChatModel
from assistantx.core.settings import Settings
from assistantx.core.task_spec import Part

ReasonerKind = Literal["symbolic", "llm", "hybrid", "cascade"]
ReasonerBuilder = Callable[[Office, Settings], ReasonerFactory]

# The PPDR reasoners: name → "module:builder"; a builder takes (office, settings).
PPDR_REASONERS: dict[str, str] = {
    "symbolic": "assistantx.agents.symbolic:build_factory",
    "llm": "assistantx.agents.llm:build_factory",
    "hybrid": "assistantx.agents.hybrid:build_factory",
    "cascade": "assistantx.agents.hybrid:build_cascade_factory",
}
ORACLE = "optimal"
REASONERS: tuple[str, ...] = (*PPDR_REASONERS, *ABLATIONS, *BASELINES, ORACLE)
LLM_REASONERS = frozenset({"llm", "hybrid", "cascade", *BASELINES})


@dataclass(frozen=True)
class OracleTask:
    """What the optimal policy is told of one task: who asks what, and what it means."""

    id: str
    requester: str
    text: str
    spec: list[Part] | None


def needs_llm(name: str, *, inner: str = "symbolic") -> bool:
    """Whether the reasoner ``name`` (an ablation: of ``inner``) asks a language model."""
    if name in ABLATIONS:
        return inner in LLM_REASONERS
    return name in LLM_REASONERS


def reasoner_factory(
    name: str,
    office: Office,
    settings: Settings,
    *,
    inner: str = "symbolic",
    task: OracleTask | None = None,
    model: ChatModel | None = None,
) -> ReasonerFactory:
    """The factory of the reasoner ``name`` (see the module's list); ReasonerError when the
    name is unknown, its part is missing, or it needs what it was not given (a ``model`` for
    the LLM reasoners, the task of ``optimal``)."""
    if name in PPDR_REASONERS:
        builder = _import(PPDR_REASONERS[name], name=name)
        factory: ReasonerFactory
        if name in LLM_REASONERS:
            from assistantx.agents.llm.shared import require_model

            factory = builder(office, settings, model=require_model(model, name))
        else:
            factory = builder(office, settings)
        return factory
    wrapper = ABLATIONS.get(name)
    if wrapper is not None:
        if inner not in PPDR_REASONERS:
            raise ReasonerError(
                f"{name} ablates a PPDR reasoner ({', '.join(PPDR_REASONERS)}), not {inner!r}"
            )
        base = reasoner_factory(inner, office, settings, model=model)

        def ablated() -> Reasoner:
            return wrapper(base())

        return ablated
    if name in BASELINES:
        # The baselines and the oracle load with the first of them built: the LLM agents and
        # the optimal policy were ~50 ms of every service start, which builds neither.
        from assistantx.agents.baselines import build_baseline_factory

        return build_baseline_factory(name, settings, model=model)
    if name == ORACLE:
        return _oracle(office, task)
    raise ReasonerError(f"unknown reasoner {name!r}; choose from {', '.join(REASONERS)}")


def load_builder(target: str, *, name: str | None = None) -> ReasonerBuilder:
    """The builder named ``"module:attr"``; ReasonerError, naming ``name`` (or the target),
    when it cannot be imported."""
    builder: ReasonerBuilder = _import(target, name=name)
    return builder


def _import(target: str, *, name: str | None) -> Callable[..., Any]:
    module_name, _, attr = target.partition(":")
    try:
        found: Callable[..., Any] = getattr(importlib.import_module(module_name), attr)
    except (ImportError, AttributeError) as exc:
        raise ReasonerError(f"the {name or target} reasoner is not available: {exc}") from exc
    return found


def _oracle(office: Office, task: OracleTask | None) -> ReasonerFactory:
    if task is None:
        raise ReasonerError("the optimal reasoner follows a task's spec: it needs the task")

    from assistantx.agents.oracle.optimal import OptimalReasoner

    def optimal() -> Reasoner:
        return OptimalReasoner.for_task(office, task.id, task.requester, task.text, task.spec)

    return optimal
