"""The dataset generator's tasks for a test's own instructions: every variant the generator
makes of them, labelled as ``dataset generate`` labels it, and the generator's own check that
the optimal policy solves each in the simulated office."""

from __future__ import annotations

from assistantx.core.office import Office
from assistantx.core.task_spec import BaseInstruction
from assistantx.evaluation.dataset.generate import _task, classify, verify_tasks
from assistantx.evaluation.dataset.tasks import Task


def every_task(office: Office, *bases: BaseInstruction) -> list[Task]:
    """Every variant of each base (all levels, achievable or not) as a task, numbered from 1
    in the generator's order."""
    variants = [v for base in bases for vs in classify(base, office).values() for v in vs]
    return [_task(v, office, n) for n, v in enumerate(variants, start=1)]


async def verify_every_variant(office: Office, base: BaseInstruction) -> list[Task]:
    """``every_task`` of ``base``, at least one achievable, each solved by the optimal policy
    as labelled (``verify_tasks`` raises DatasetError on a count, outcome or goal)."""
    tasks = every_task(office, base)
    assert any(t.achievable for t in tasks)
    await verify_tasks(office, tasks)
    return tasks
