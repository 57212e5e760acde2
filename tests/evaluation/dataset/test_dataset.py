"""The generated dataset: current, the paper's mix, and every task solved by the optimal policy."""

from __future__ import annotations

from collections import Counter
from pathlib import Path

import pytest

from assistantx.agents.oracle.plan import candidates
from assistantx.core.errors import DatasetError
from assistantx.core.office import DEFAULT_OFFICE, Office, load_office
from assistantx.evaluation.dataset import (
    build_plan,
    dump_tasks,
    generate,
    load_base_instructions,
    load_tasks,
    order_candidates,
    run_optimal,
)
from assistantx.memory.graph import LongTermMemory

DATASET = DEFAULT_OFFICE.parent
FIXTURES = Path(__file__).parent / "fixtures"


@pytest.fixture(scope="module")
def office() -> Office:
    return load_office()


def test_committed_file_is_current(office: Office) -> None:
    bases = load_base_instructions(DATASET / "base_instructions.yaml", office)
    assert len(bases) == 30
    regenerated = dump_tasks(generate(office, bases, seed=0))
    committed = (DATASET / "tasks.jsonl").read_text(encoding="utf-8")
    assert regenerated == committed, "run: assistantx dataset generate --seed 0"


def test_generation_is_deterministic_per_seed(office: Office) -> None:
    bases = load_base_instructions(DATASET / "base_instructions.yaml", office)
    a = [t.unavailable for t in generate(office, bases, seed=3)]
    b = [t.unavailable for t in generate(office, bases, seed=3)]
    c = [t.unavailable for t in generate(office, bases, seed=4)]
    assert a == b
    assert a != c


def test_target_mix_and_fields(office: Office) -> None:
    tasks = load_tasks(DATASET / "tasks.jsonl", office)
    mix = Counter((t.level, t.achievable) for t in tasks)
    assert mix == {("L1", True): 90, ("L2", True): 73, ("L3", True): 25, ("L3", False): 22}
    assert len({t.base for t in tasks}) == 30
    kinds = {k for t in tasks for k in t.kind}
    assert kinds >= {"fetch", "deliver", "print", "copy", "sign", "seal", "coffee", "water"}
    assert kinds >= {"heat", "snack", "forward_file", "get_file"}
    assert any(len(t.kind) > 1 for t in tasks)  # combinations
    for t in tasks:
        assert t.requester not in t.unavailable
        assert {"informed": t.requester} in t.goal
        assert len({tuple(sorted(x.unavailable)) for x in tasks if x.base == t.base}) == sum(
            1 for x in tasks if x.base == t.base
        )


async def test_every_task_is_solved_by_the_optimal_policy_in_exactly_optimal_actions(
    office: Office,
) -> None:
    tasks = load_tasks(DATASET / "tasks.jsonl", office)
    for task in tasks:
        count, reached, outcome = await run_optimal(office, task)
        assert count == task.optimal_actions, task.id
        assert all(reached), (task.id, reached)
        assert outcome == ("done" if task.achievable else "unachievable"), task.id


def test_levels_follow_availability(office: Office) -> None:
    tasks = {(t.base, tuple(t.unavailable)): t for t in load_tasks(DATASET / "tasks.jsonl")}
    # b01: Lee asks for a stapler; Wang (known, nearest) then Zhang (known); Hu, Gao unknown
    l1 = tasks[("b01", ())]
    assert (l1.level, l1.optimal_actions) == ("L1", 9)
    l2 = [t for (b, _), t in tasks.items() if b == "b01" and t.level == "L2"]
    assert l2 and all("wang" in t.unavailable and "zhang" not in t.unavailable for t in l2)
    assert all(t.optimal_actions == 11 for t in l2)  # one more inquire + wait
    l3 = [t for (b, _), t in tasks.items() if b == "b01" and t.level == "L3" and t.achievable]
    assert all({"wang", "zhang"} <= set(t.unavailable) for t in l3)


def test_candidate_order_is_nearest_first(office: Office) -> None:
    bases = load_base_instructions(DATASET / "base_instructions.yaml", office)
    base = next(b for b in bases if b.id == "b01")
    role = build_plan(base, office).roles[0]
    people = candidates(role, LongTermMemory(office), base.requester)
    assert sorted(people) == ["wang", "zhang"]  # Hu's and Gao's staplers are unknown
    home = office.robot.home
    order = order_candidates(office, role, people, home)
    assert order == sorted(people, key=lambda p: office.distance(home, office.person(p).location))


def test_bad_base_instruction_is_a_clear_error(office: Office, tmp_path: Path) -> None:
    bad = tmp_path / "base.yaml"
    bad.write_text(
        "instructions:\n- id: x\n  requester: zhang\n  text: take my book to Lee\n"
        "  parts: [{kind: deliver, item: book, to: lee}]\n"
    )
    with pytest.raises(DatasetError, match="the requester owns no book"):
        load_base_instructions(bad, office)
    bad.write_text("instructions:\n- id: x\n  requester: lee\n  text: t\n  parts: [{kind: fly}]\n")
    with pytest.raises(DatasetError, match=r"instructions\[0\]\.parts"):
        load_base_instructions(bad, office)


def test_a_recipient_on_a_fetch_part_is_refused_not_dropped(office: Office, tmp_path: Path) -> None:
    """A blind writer's "bring Kwame a pair of gloves" written as a fetch with ``to:`` had its
    recipient dropped silently (the goal had the requester holding the gloves)."""
    bad = tmp_path / "base.yaml"
    bad.write_text(
        "instructions:\n- id: x\n  requester: lee\n  text: bring Wang a stapler\n"
        "  parts: [{kind: fetch, item: stapler, to: wang}]\n"
    )
    with pytest.raises(DatasetError, match="fetch brings the item to the requester"):
        load_base_instructions(bad, office)
    # the requester's own fetch, with no recipient, is read as before
    bad.write_text(
        "instructions:\n- id: x\n  requester: lee\n  text: bring me a stapler\n"
        "  parts: [{kind: fetch, item: stapler}]\n"
    )
    assert [b.id for b in load_base_instructions(bad, office)] == ["x"]


def test_bad_task_line_names_the_line(office: Office, tmp_path: Path) -> None:
    good = (DATASET / "tasks.jsonl").read_text().splitlines()[0]
    file = tmp_path / "tasks.jsonl"
    file.write_text(good + "\n" + good.replace('"L1"', '"L7"').replace("t001", "t002") + "\n")
    with pytest.raises(DatasetError, match=r"tasks.jsonl:2: level"):
        load_tasks(file, office)
    file.write_text(good.replace('"requester": "lee"', '"requester": "nobody"') + "\n")
    with pytest.raises(DatasetError, match=r":1: .*nobody"):
        load_tasks(file, office)


async def test_fixture_tasks_match_the_small_office() -> None:
    small = load_office(FIXTURES / "office.yaml")
    for task in load_tasks(FIXTURES / "tasks.jsonl", small):
        if task.spec is None:
            continue
        count, reached, outcome = await run_optimal(small, task)
        assert (count, all(reached)) == (task.optimal_actions, True), task.id
        assert outcome == ("done" if task.achievable else "unachievable")
