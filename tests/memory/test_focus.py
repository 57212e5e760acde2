"""What an LLM agent sees of memory: the task's part, capped to the context."""

from __future__ import annotations

import importlib.util
from pathlib import Path
from types import ModuleType

import pytest

from assistantx.adapters.model import estimate_tokens
from assistantx.core.office import Office, load_office
from assistantx.core.trace import Trace
from assistantx.memory.focus import focus_budget, render_focused, task_focus
from assistantx.memory.graph import LongTermMemory
from assistantx.memory.short_term import ShortTermMemory

BENCH = Path(__file__).resolve().parents[2] / "bench" / "prompt_sizes.py"


def _bench() -> ModuleType:
    spec = importlib.util.spec_from_file_location("prompt_sizes", BENCH)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.fixture(scope="module")
def office() -> Office:
    return load_office()


def _stm(text: str) -> ShortTermMemory:
    trace = Trace(instruction_id="i", requester="lee", text=text, reasoner="llm", started_at=0)
    return ShortTermMemory(instruction_id="i", requester="lee", text=text, trace=trace)


def test_the_focus_holds_the_requester_named_people_and_the_item_owners(office: Office) -> None:
    ltm = LongTermMemory(office)
    focus = task_focus(ltm, _stm("Could you bring me Zhang Wei's stapler?"))
    assert focus.people[0] == "lee"
    assert "zhang" in focus.people
    assert "stapler" in focus.items
    assert set(ltm.owners("stapler")) - {"lee"} <= set(focus.people)
    assert ltm.groups_of("lee") and set(ltm.groups_of("lee")) <= set(focus.groups)
    # people with nothing to do with the task are left out
    assert len(focus.people) < len(office.people)


def test_the_people_shown_are_capped_and_the_rest_counted() -> None:
    ltm = LongTermMemory(_bench().large_office(200))
    focus = task_focus(ltm, _stm("Could you get me a stapler, please?"))
    budget = focus_budget(2600 + 512 + 3 * 24, 512)  # room for the minimum of 6 people
    text = render_focused(ltm, _stm("x"), focus, budget)
    rows = [line for line in text.splitlines() if line.startswith("- ") and " | " in line]
    people_rows = [r for r in rows if r.count(" | ") == 5]
    assert len(focus.people) > 6
    assert len(people_rows) == budget.max_people == 6
    assert f"(and {len(focus.people) - 6} more people" in text


def test_every_prompt_fits_4k_tokens_on_a_1000_person_office() -> None:
    bench = _bench()
    big = bench.large_office(1000)
    assert len(big.people) == 1000
    prompts = bench.prompts_for(big, 4096, 512)
    sizes = {k: estimate_tokens("".join(m.content for m in v)) for k, v in prompts.items()}
    assert len(sizes) == 2 * 9  # 4 agents and 5 baselines, at step 0 and step 6
    too_big = {k: v for k, v in sizes.items() if v >= 4096 - 512}
    assert not too_big
