"""One instruction run as an achievable L1 task by the symbolic PPDR method in the simulated
office: the episode the reader's end-to-end tests judge with ``evaluation.metrics``."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from assistantx.core.office import Office
from assistantx.core.settings import Settings
from assistantx.core.task_schema import Part
from assistantx.evaluation.dataset.tasks import Task
from assistantx.evaluation.episode import Episode
from assistantx.evaluation.harness import run_episode
from assistantx.evaluation.methods import MethodBuilder, MethodSpec


def l1_task(
    requester: str,
    instruction: str,
    goal: list[dict[str, Any]],
    spec: Sequence[Part] | None = None,
) -> Task:
    """The task of one instruction, its goal as given, solved in one action at best."""
    return Task(
        id="t001",
        base="b1",
        level="L1",
        achievable=True,
        requester=requester,
        instruction=instruction,
        goal=goal,
        optimal_actions=1,
        spec=list(spec) if spec is not None else None,
    )


async def ppdr_episode(
    office: Office,
    requester: str,
    instruction: str,
    goal: list[dict[str, Any]],
    spec: Sequence[Part] | None = None,
) -> Episode:
    """``instruction`` run by the symbolic PPDR method in ``office``'s simulation."""
    task = l1_task(requester, instruction, goal, spec)
    return await run_episode(task, 0, office, MethodBuilder(MethodSpec("ppdr"), office, Settings()))
