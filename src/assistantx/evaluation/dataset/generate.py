"""Generate the task file from an office and its base instructions.

For each base instruction the generator enumerates who could matter (the role candidates in
memory, everyone able to fill a role in truth, and the people told without being asked),
classifies every set of them being away by playing the optimal policy against the truth
(``policy.dry_run``), and then draws, with a seeded generator, the availability variants that
make the target mix: per base three L1 variants (everyone needed is available; people who do
not matter may be away), then L2, achievable-L3 and unachievable variants spread round-robin
over the bases that have them, each with at most one bystander away as well.

Labels (level, achievability, goal, ``optimal_actions``) are computed, never typed. With
``verify`` every task is then run through the simulated office by the optimal policy, and the
run must take exactly the dry run's actions and reach every milestone (else DatasetError).
"""

from __future__ import annotations

import asyncio
import itertools
import logging
import random
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import Any

from assistantx.agents.oracle.optimal import OptimalReasoner
from assistantx.agents.oracle.plan import TaskPlan, able, build_plan, candidates
from assistantx.agents.oracle.policy import DryRun, dry_run
from assistantx.core.errors import DatasetError
from assistantx.core.office import Office, PersonId
from assistantx.core.task_spec import BaseInstruction
from assistantx.evaluation.dataset.tasks import Level, Task
from assistantx.memory.graph import LongTermMemory
from assistantx.runtime.loop import LoopLimits
from assistantx.sim.run import run_in_sim

# The paper's mix (DESIGN §5).
TARGET_L1_PER_BASE = 3
TARGETS: dict[str, int] = {"L2": 73, "L3": 25, "unachievable": 22}
MAX_CORE_SIZE = 5
# Related people whose absence is varied (the first ones ``related_people`` returns): the
# default office has at most 5 per base; a generated office of 1,024 people has hundreds, and
# every combination of them would be a dry run.
MAX_RELATED = 8

Category = str  # "L1", "L2", "L3" (achievable) or "unachievable"

logger = logging.getLogger(__name__)


@dataclass(frozen=True)
class Variant:
    base: BaseInstruction
    unavailable: frozenset[str]
    category: Category
    run: DryRun


def related_people(
    plan: TaskPlan, office: Office, ltm: LongTermMemory, requester: str
) -> list[str]:
    """Everyone whose absence can change what the optimal agent does."""
    found: set[str] = set(plan.must_be_available)
    for role in [*plan.roles, *(plan.fallback.roles if plan.fallback else ())]:
        found.update(candidates(role, ltm, requester))
        found.update(p.id for p in office.people if able(role, office, p.id))
    found.discard(requester)
    return sorted(found)


def category_of(run: DryRun) -> Category:
    if not run.log.achievable:
        return "unachievable"
    return run.log.level


def classify(base: BaseInstruction, office: Office) -> dict[Category, list[Variant]]:
    """Every set of related people being away, by category (the 'cores' of the variants)."""
    plan = build_plan(base, office)
    ltm = LongTermMemory(office)
    related = related_people(plan, office, ltm, base.requester)[:MAX_RELATED]
    pools: dict[Category, list[Variant]] = {}
    for size in range(min(len(related), MAX_CORE_SIZE) + 1):
        for core in itertools.combinations(related, size):
            away = frozenset(core)
            if away & plan.must_be_available:
                continue  # they would silently miss a message: not a fair variant
            run = dry_run(base, plan, office, set(away), ltm)
            category = category_of(run)
            pools.setdefault(category, []).append(Variant(base, away, category, run))
    return pools


def generate(
    office: Office, bases: Sequence[BaseInstruction], seed: int = 0, *, verify: bool = False
) -> list[Task]:
    rng = random.Random(seed)
    pools = {b.id: classify(b, office) for b in bases}
    chosen: list[Variant] = []
    for base in bases:
        _require_l1_with_everyone_in(base, pools[base.id])
        chosen += _pick_l1(base, office, pools[base.id].get("L1", []), rng)
    for category, target in TARGETS.items():
        chosen += _pick_round_robin(bases, office, pools, category, target, rng)
    order = {b.id: n for n, b in enumerate(bases)}
    rank = {"L1": 0, "L2": 1, "L3": 2, "unachievable": 3}
    chosen.sort(key=lambda v: (order[v.base.id], rank[v.category], sorted(v.unavailable)))
    tasks = [_task(v, office, n) for n, v in enumerate(chosen, start=1)]
    if verify:
        asyncio.run(verify_tasks(office, tasks))
    return tasks


def _require_l1_with_everyone_in(
    base: BaseInstruction, pool: dict[Category, list[Variant]]
) -> None:
    """Every base instruction's tasks start from the run with everyone in, which must be L1
    (achievable without a fallback); a base whose parts the optimal agent cannot do then (an
    ownerless fetch of a kind only the requester has, say) is a mistake in the base, told in
    one line, where it was a bare StopIteration."""
    if any(not v.unavailable for v in pool.get("L1", [])):
        return
    category = next(
        (c for c, variants in pool.items() for v in variants if not v.unavailable), "no run"
    )
    found = "unachievable" if category == "unachievable" else f"{category}, not L1"
    raise DatasetError(
        f"base instruction {base.id!r} ({base.text!r}): with everyone in, the optimal agent's"
        f" run is {found}; check its parts (the item's owner, who is asked, where it is kept)"
    )


def _bystanders(base: BaseInstruction, office: Office) -> list[str]:
    plan = build_plan(base, office)
    related = set(related_people(plan, office, LongTermMemory(office), base.requester))
    return [p.id for p in office.people if p.id not in related and p.id != base.requester]


def _pick_l1(
    base: BaseInstruction, office: Office, pool: list[Variant], rng: random.Random
) -> list[Variant]:
    bystanders = _bystanders(base, office)
    everyone = next(v for v in pool if not v.unavailable)
    picked = [everyone]
    later_away = [v for v in pool if v.unavailable]  # e.g. a farther candidate is away
    rng.shuffle(later_away)
    if later_away:
        picked.append(_with_bystander(later_away[0], bystanders, rng, chance=0.5))
    while len(picked) < TARGET_L1_PER_BASE:
        extra = frozenset(rng.sample(bystanders, k=min(len(bystanders), len(picked))))
        candidate = Variant(base, extra, "L1", everyone.run)
        if candidate.unavailable not in {v.unavailable for v in picked}:
            picked.append(candidate)
    return picked


def _with_bystander(
    variant: Variant, bystanders: list[str], rng: random.Random, chance: float
) -> Variant:
    if not bystanders or rng.random() >= chance:
        return variant
    extra = rng.choice(bystanders)
    return Variant(variant.base, variant.unavailable | {extra}, variant.category, variant.run)


def _pick_round_robin(
    bases: Sequence[BaseInstruction],
    office: Office,
    pools: dict[str, dict[Category, list[Variant]]],
    category: Category,
    target: int,
    rng: random.Random,
) -> list[Variant]:
    """Spread ``target`` variants over the bases that have this category, one base at a time.

    Each base offers its cores smallest first (shuffled within a size); once they are used up
    it offers them again with a bystander away, so small pools still give distinct variants.
    """
    queues: dict[str, list[Variant]] = {}
    for base in bases:
        pool = sorted(pools[base.id].get(category, []), key=lambda v: sorted(v.unavailable))
        rng.shuffle(pool)
        pool.sort(key=lambda v: len(v.unavailable))
        if pool:
            queues[base.id] = pool
    if not queues:
        # A large office has more alternatives than a core can make unavailable at once, so
        # no base reaches this category: the dataset goes without it rather than crashing.
        logger.warning("no base instruction has %s variants in this office", category)
        return []
    order = [b for b in bases if b.id in queues]
    rng.shuffle(order)
    bystanders = {b.id: _bystanders(b, office) for b in order}
    used: set[tuple[str, frozenset[str]]] = set()
    picked: list[Variant] = []
    for round_number in itertools.count():
        progressed = False
        for base in order:
            if len(picked) >= target:
                return picked
            queue = queues[base.id]
            core = queue[round_number % len(queue)]
            variant = core if round_number < len(queue) else None
            if variant is None or rng.random() < 0.3:
                variant = _with_bystander(core, bystanders[base.id], rng, chance=1.0)
            if (base.id, variant.unavailable) in used:
                continue
            used.add((base.id, variant.unavailable))
            picked.append(variant)
            progressed = True
        if not progressed and round_number > 4 * max(len(q) for q in queues.values()):
            # a small office (few bases, few people to be away) has fewer distinct variants:
            # the dataset takes them all rather than refusing the office
            logger.warning(
                "only %d distinct %s variants in this office (%d wanted): all are used",
                len(picked),
                category,
                target,
            )
            return picked
    return picked  # pragma: no cover - the loop returns


def _asked(base: BaseInstruction, plan: TaskPlan, office: Office) -> list[dict[str, Any]]:
    """What an unachievable task asked for, whose parts that can be done may be done: a thing
    nobody's was named for comes from where one is kept, or is a colleague's lent with their
    own yes (the fallback the planner and the oracle take when the keeper is away)."""
    if not plan.uses_kept:
        return plan.goal
    lent = (plan.fallback or build_plan(base, office, kept=False)).goal
    return [*plan.goal, *(m for m in lent if m not in plan.goal)]


def _task(variant: Variant, office: Office, number: int) -> Task:
    base = variant.base
    plan = build_plan(base, office)
    achievable = variant.category != "unachievable"
    level: Level = "L3" if not achievable else variant.run.log.level
    if variant.run.log.fell_back and plan.fallback is not None:
        plan = plan.fallback  # a colleague's was borrowed: any of the type will do
    goal = plan.goal if achievable else [{"informed": base.requester}]
    extra = {} if achievable else {"requested_goal": _asked(base, plan, office)}
    return Task(
        id=f"t{number:03d}",
        base=base.id,
        level=level,
        achievable=achievable,
        requester=base.requester,
        instruction=base.text,
        unavailable=sorted(variant.unavailable),
        goal=goal,
        optimal_actions=len(variant.run.actions),
        kind=base.kinds,
        spec=list(base.parts),
        **extra,
    )


async def run_optimal(office: Office, task: Task) -> tuple[int, list[bool], str | None]:
    """Play the optimal policy for one task in a fresh simulated office.

    Returns the number of actions it executed, which goal milestones hold, and its outcome.
    """
    reasoner = OptimalReasoner.for_task(
        office, task.id, task.requester, task.instruction, task.spec
    )
    run = await run_in_sim(
        office,
        PersonId(task.requester),  # an id of the office: the task was built from it
        task.instruction,
        lambda: reasoner,
        unavailable=task.unavailable,
        limits=LoopLimits(max_steps=60),
        reasoner_name="optimal",
    )
    count = len(run.trace.actions())
    return count, run.sim.check(task.goal), run.trace.outcome


async def verify_tasks(office: Office, tasks: Iterable[Task]) -> None:
    for task in tasks:
        count, reached, outcome = await run_optimal(office, task)
        expected = "done" if task.achievable else "unachievable"
        if count != task.optimal_actions or not all(reached) or outcome != expected:
            raise DatasetError(
                f"task {task.id} ({task.base}, away {task.unavailable}): the optimal policy took "
                f"{count} actions (expected {task.optimal_actions}), ended {outcome!r} "
                f"(expected {expected!r}), milestones {reached}"
            )
