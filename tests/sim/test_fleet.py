"""Several robots serving one office (sim.fleet, runtime.fleet): the robot an instruction gets,
the lease per robot, each robot's own locker, parking, and instructions that run at once."""

from __future__ import annotations

import asyncio
from pathlib import Path

from assistantx.agents.registry import reasoner_factory
from assistantx.core.office import PersonId, load_office
from assistantx.core.settings import Settings
from assistantx.evaluation.dataset import load_tasks
from assistantx.runtime.loop import LoopLimits
from assistantx.sim.fleet import sim_fleet
from assistantx.sim.requester import Wish
from assistantx.sim.virtual_time import LoopClock, run_virtual

TASKS = Path(__file__).resolve().parents[2] / "dataset" / "tasks.jsonl"


def test_a_free_robot_nearest_the_first_stop_is_given_then_the_first_to_come_free() -> None:
    async def scenario() -> list[str]:
        fleet = sim_fleet(load_office(), LoopClock(), 2)
        lease, seen = fleet.lease, []
        async with fleet:
            # parking 2 is at the west end of the desks' middle aisle, next to desk_09
            await lease.acquire("a", toward="desk_09")
            seen.append(lease.body_of("a").name)  # type: ignore[union-attr]
            await lease.acquire("b", toward="desk_09")  # the nearer one is taken: the other
            seen.append(lease.body_of("b").name)  # type: ignore[union-attr]
            queued: list[list[str]] = []
            waiting = asyncio.ensure_future(lease.acquire("c", queued.append))
            await asyncio.sleep(0)
            assert not waiting.done() and queued == [["a", "b", "c"]]
            lease.release("a")
            await waiting
            seen.append(lease.body_of("c").name)  # type: ignore[union-attr]
            lease.release("b")  # nobody waits: robot 1 drives back to its parking place
            await asyncio.sleep(600)
            seen.append(str(fleet.bodies[0].robot.state().place))
            # What "a" left aboard goes back with robot 2 (its locker holds it), not with the
            # free robot 1: the errand waits for robot 2.
            errand = asyncio.ensure_future(lease.acquire("a.return"))
            await asyncio.sleep(0)
            assert not errand.done()
            lease.release("c")
            await errand
            seen.append(lease.body_of("a.return").name)  # type: ignore[union-attr]
        return seen

    assert run_virtual(scenario) == ["robot 2", "robot 1", "robot 2", "parking 1", "robot 2"]


def test_two_instructions_at_once_are_served_by_two_robots_with_their_own_lockers() -> None:
    """Two requests released together: each robot serves one, each hand-over opens the
    locker of the robot that carries the item, both requesters get what they asked for,
    and the robots never touch."""
    office = load_office()
    tasks = [t for t in load_tasks(TASKS) if not t.unavailable and t.kind == ["fetch"]]
    first = tasks[0]
    second = next(t for t in tasks if t.requester != first.requester)

    async def scenario() -> tuple[list[str | None], list[int], list[list[bool]], int, float]:
        fleet = sim_fleet(office, LoopClock(), 2)
        assistant = fleet.assistant(
            reasoner_factory("symbolic", office, Settings()),
            limits=LoopLimits(deadline_s=3 * 3600.0, wall_s=None),
        )
        async with fleet:
            await assistant.start()
            try:
                for n, task in enumerate((first, second)):
                    fleet.wishes[f"i{n}"] = Wish.from_goal(office, task.requester, task.goal)
                    await assistant.submit(
                        PersonId(task.requester), task.instruction, instruction_id=f"i{n}"
                    )
                ended = [await assistant.wait(f"i{n}") for n in range(2)]
            finally:
                await assistant.stop()
        accepted = [
            sum(e.kind == "code_accepted" for e in body.locker.controller.events_since(0).events)  # type: ignore[attr-defined]
            for body in fleet.bodies
        ]
        goals = [fleet.sim.check(t.goal) for t in (first, second)]
        return (
            [s.trace.outcome for s in ended],
            accepted,
            goals,
            fleet.traffic.contacts,
            fleet.traffic.separation_m,
        )

    outcomes, accepted, goals, contacts, separation = run_virtual(scenario)
    assert outcomes == ["done", "done"]
    assert all(n > 0 for n in accepted)  # both robots' lockers were opened
    assert goals == [[True] * len(first.goal), [True] * len(second.goal)]
    assert contacts == 0 and separation >= 0.5
