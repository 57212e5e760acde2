"""One registry knows every reasoner by name; serve, run and eval build them there."""

from __future__ import annotations

import pytest

from assistantx.adapters.model import model_from_settings
from assistantx.agents.ablations import ABLATIONS, NoPerception
from assistantx.agents.baseline_names import BASELINES
from assistantx.agents.baselines import BaselineReasoner
from assistantx.agents.hybrid import HybridReasoner
from assistantx.agents.llm import LLMReasoner
from assistantx.agents.oracle.optimal import OptimalReasoner
from assistantx.agents.registry import (
    PPDR_REASONERS,
    REASONERS,
    OracleTask,
    load_builder,
    needs_llm,
    reasoner_factory,
)
from assistantx.agents.symbolic import SymbolicReasoner
from assistantx.core.errors import ReasonerError
from assistantx.core.office import DEFAULT_OFFICE, Office, load_office
from assistantx.core.settings import Settings
from assistantx.evaluation.dataset import load_tasks

# Building a factory opens no connection; nothing listens here and nothing is asked. The
# model is injected, as the composition root (service, CLI, bench) does.
LLM = Settings(llm_base_url="http://127.0.0.1:9/v1", llm_model="none")
MODEL = model_from_settings(LLM)


@pytest.fixture(scope="module")
def office() -> Office:
    return load_office()


@pytest.fixture(scope="module")
def oracle_task(office: Office) -> OracleTask:
    task = load_tasks(DEFAULT_OFFICE.parent / "tasks.jsonl", office)[0]
    return OracleTask(task.id, task.requester, task.instruction, task.spec)


EXPECTED = {
    "symbolic": SymbolicReasoner,
    "llm": LLMReasoner,
    "hybrid": HybridReasoner,
    "cascade": HybridReasoner,
    **dict.fromkeys(ABLATIONS, object),  # checked in their own test below
    **dict.fromkeys(BASELINES, BaselineReasoner),
    "optimal": OptimalReasoner,
}


def test_the_registry_lists_every_reasoner_the_commands_offer() -> None:
    assert set(REASONERS) == set(EXPECTED)
    assert list(PPDR_REASONERS) == ["symbolic", "llm", "hybrid", "cascade"]  # --reasoner


@pytest.mark.parametrize("name", REASONERS)
def test_each_name_builds_its_reasoner(name: str, office: Office, oracle_task: OracleTask) -> None:
    factory = reasoner_factory(name, office, LLM, task=oracle_task, model=MODEL)
    reasoner = factory()
    assert isinstance(reasoner, EXPECTED[name])
    if name in BASELINES:
        assert reasoner.name == name


@pytest.mark.parametrize("name", ABLATIONS)
@pytest.mark.parametrize("inner", ["symbolic", "llm"])
def test_an_ablation_wraps_the_chosen_ppdr_reasoner(name: str, inner: str, office: Office) -> None:
    reasoner = reasoner_factory(name, office, LLM, inner=inner, model=MODEL)()
    assert isinstance(reasoner, ABLATIONS[name])
    assert isinstance(reasoner.inner, (SymbolicReasoner if inner == "symbolic" else LLMReasoner))
    assert reasoner.name == f"{inner}-{name.removeprefix('ppdr-')}"
    assert needs_llm(name, inner=inner) == (inner == "llm")


def test_an_ablation_of_a_baseline_is_refused(office: Office) -> None:
    with pytest.raises(ReasonerError, match="ablates a PPDR reasoner"):
        reasoner_factory("ppdr-no-planning", office, LLM, inner="react")
    assert isinstance(reasoner_factory("ppdr-no-perception", office, LLM)(), NoPerception)


def test_unknown_names_and_missing_parts_are_one_clear_error(office: Office) -> None:
    with pytest.raises(ReasonerError, match=r"unknown reasoner 'magic'; choose from symbolic, llm"):
        reasoner_factory("magic", office, Settings())
    unset = Settings(llm_base_url=None)
    assert model_from_settings(unset) is None
    with pytest.raises(ReasonerError, match="the llm reasoner needs a language model: set ASSIS"):
        reasoner_factory("llm", office, unset, model=model_from_settings(unset))
    with pytest.raises(ReasonerError, match="the cot reasoner needs a language model"):
        reasoner_factory("cot", office, LLM)  # a URL in the settings is not a model
    with pytest.raises(ReasonerError, match="the hybrid reasoner needs a language model"):
        reasoner_factory("ppdr-no-reflection", office, LLM, inner="hybrid")
    with pytest.raises(ReasonerError, match="cannot use the LLM at localhost:1/v1"):
        model_from_settings(Settings(llm_base_url="localhost:1/v1"))
    with pytest.raises(ReasonerError, match="it needs the task"):
        reasoner_factory("optimal", office, Settings())
    with pytest.raises(ReasonerError, match="the nowhere:build reasoner is not available"):
        load_builder("nowhere:build")
    with pytest.raises(ReasonerError, match="not available"):
        load_builder("assistantx.agents.symbolic:no_such_builder")


def test_which_reasoners_ask_a_model() -> None:
    assert {n for n in REASONERS if needs_llm(n)} == {"llm", "hybrid", "cascade", *BASELINES}
