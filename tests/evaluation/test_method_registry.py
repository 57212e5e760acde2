"""The harness takes its reasoners from the one registry; only ``ppdr`` and the per-task
optimal policy are its own."""

from __future__ import annotations

import pytest

from assistantx.adapters.model import model_from_settings
from assistantx.agents.ablations import NoPlanning
from assistantx.agents.baselines import BaselineFactory
from assistantx.agents.oracle.optimal import OptimalReasoner
from assistantx.agents.symbolic import SymbolicReasoner
from assistantx.core.errors import ReasonerError
from assistantx.core.office import DEFAULT_OFFICE, Office, load_office
from assistantx.core.ports.model import ChatModel
from assistantx.core.settings import Settings
from assistantx.evaluation.dataset import load_tasks
from assistantx.evaluation.dataset.tasks import Task
from assistantx.evaluation.methods import METHODS, MethodBuilder, MethodSpec


@pytest.fixture(scope="module")
def office() -> Office:
    return load_office()


@pytest.fixture(scope="module")
def task(office: Office) -> Task:
    return load_tasks(DEFAULT_OFFICE.parent / "tasks.jsonl", office)[0]


def test_ppdr_is_the_chosen_reasoner_and_ablations_wrap_it(office: Office, task: Task) -> None:
    ppdr = MethodBuilder(MethodSpec("ppdr"), office, Settings()).factory(task)()
    assert isinstance(ppdr, SymbolicReasoner)
    ablated = MethodBuilder(MethodSpec("ppdr-no-planning"), office, Settings()).factory(task)()
    assert isinstance(ablated, NoPlanning) and isinstance(ablated.inner, SymbolicReasoner)


def test_the_optimal_policy_is_told_each_task(office: Office, task: Task) -> None:
    builder = MethodBuilder(MethodSpec("optimal"), office, Settings())
    reasoner = builder.factory(task)()
    assert isinstance(reasoner, OptimalReasoner)
    assert (reasoner.base.id, reasoner.base.requester) == (task.id, task.requester)


def test_methods_are_the_registry_names_plus_ppdr() -> None:
    from assistantx.agents.registry import PPDR_REASONERS, REASONERS

    assert set(METHODS) == (set(REASONERS) - set(PPDR_REASONERS)) | {"ppdr"}
    assert MethodSpec("ppdr", "hybrid").needs_llm and not MethodSpec("ppdr").needs_llm
    assert MethodSpec("react").needs_llm and not MethodSpec("optimal", "llm").needs_llm


def test_a_missing_llm_is_a_reasoner_error(office: Office) -> None:
    with pytest.raises(ReasonerError, match="needs a language model: set ASSISTANTX_LLM_BASE_URL"):
        MethodBuilder(MethodSpec("ppdr", "llm"), office, Settings(llm_base_url=None))
    with pytest.raises(ReasonerError, match="needs a language model"):
        MethodBuilder(
            MethodSpec("ppdr", "llm"),
            office,
            Settings(llm_base_url=None),
            build_model=model_from_settings,
        )


def test_the_llm_methods_get_the_model_the_caller_builds(office: Office) -> None:
    settings = Settings(llm_base_url="http://127.0.0.1:9/v1", llm_model="none")
    built: list[Settings] = []

    def build(given: Settings) -> ChatModel | None:
        built.append(given)
        return model_from_settings(given)

    MethodBuilder(MethodSpec("ppdr"), office, settings, build_model=build)
    assert built == []  # the symbolic PPDR needs no model: none is built
    builder = MethodBuilder(MethodSpec("react"), office, settings, build_model=build)
    assert built == [settings]
    assert isinstance(builder._shared, BaselineFactory)
    assert builder._shared.shared.model.base_url == "http://127.0.0.1:9/v1"  # type: ignore[attr-defined]
