"""The task dataset: base instructions, their meaning, the optimal policy and the generator."""

from assistantx.agents.oracle.optimal import OptimalReasoner
from assistantx.agents.oracle.plan import TaskPlan, build_plan
from assistantx.agents.oracle.policy import dry_run, order_candidates
from assistantx.core.task_spec import BaseInstruction, Part, load_base_instructions
from assistantx.evaluation.dataset.generate import generate, run_optimal, verify_tasks
from assistantx.evaluation.dataset.tasks import (
    LEVELS,
    Level,
    Task,
    dump_tasks,
    load_tasks,
    office_for_tasks,
)

__all__ = [
    "LEVELS",
    "BaseInstruction",
    "Level",
    "OptimalReasoner",
    "Part",
    "Task",
    "TaskPlan",
    "build_plan",
    "dry_run",
    "dump_tasks",
    "generate",
    "load_base_instructions",
    "load_tasks",
    "office_for_tasks",
    "order_candidates",
    "run_optimal",
    "verify_tasks",
]
