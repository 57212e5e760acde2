"""The task file (DESIGN §5): one JSON task per line, loaded and checked.

Required fields: ``id``, ``base``, ``level`` (L1/L2/L3), ``achievable``, ``requester``,
``instruction``, ``unavailable``, ``goal`` (milestones), ``optimal_actions``. The generator
adds ``kind`` (the part kinds) and ``spec`` (the base instruction's parts, so the optimal
policy can replay the task); any other task file may leave them out.
"""

from __future__ import annotations

import json
from collections.abc import Iterable
from pathlib import Path
from typing import Any, Literal

from pydantic import BaseModel, ConfigDict, Field, ValidationError, field_validator

from assistantx.core.errors import DatasetError
from assistantx.core.goals import parse_milestone
from assistantx.core.office import Office
from assistantx.core.task_spec import Part

Level = Literal["L1", "L2", "L3"]
LEVELS: tuple[Level, ...] = ("L1", "L2", "L3")


class Task(BaseModel):
    model_config = ConfigDict(extra="allow", frozen=True)

    id: str = Field(min_length=1)
    base: str
    level: Level
    achievable: bool
    requester: str
    instruction: str = Field(min_length=1)
    unavailable: list[str] = Field(default_factory=list)
    goal: list[dict[str, Any]] = Field(min_length=1)
    optimal_actions: int = Field(ge=1)
    kind: list[str] = Field(default_factory=list)
    spec: list[Part] | None = None

    @field_validator("goal")
    @classmethod
    def _milestones(cls, goal: list[dict[str, Any]]) -> list[dict[str, Any]]:
        for milestone in goal:
            parse_milestone(milestone)
        return goal


def check_task(task: Task, office: Office) -> None:
    """Every person the task names must be in the office (raises KeyError)."""
    office.person(task.requester)
    for person in task.unavailable:
        office.person(person)
    if task.requester in task.unavailable:
        raise ValueError("the requester cannot be unavailable")


def load_tasks(path: str | Path, office: Office | None = None) -> list[Task]:
    """Read a task file; a bad line raises DatasetError naming the file and the line."""
    file = Path(path)
    try:
        lines = file.read_text(encoding="utf-8").splitlines()
    except OSError as exc:
        raise DatasetError(f"{file}: cannot be read: {exc.strerror or exc}") from exc
    tasks: list[Task] = []
    seen: set[str] = set()
    for number, line in enumerate(lines, start=1):
        if not line.strip():
            continue
        try:
            task = Task.model_validate_json(line)
            if office is not None:
                check_task(task, office)
        except ValidationError as exc:
            err = exc.errors()[0]
            where = ".".join(str(p) for p in err["loc"]) or "line"
            raise DatasetError(f"{file}:{number}: {where}: {err['msg']}") from exc
        except (KeyError, ValueError) as exc:
            raise DatasetError(f"{file}:{number}: {exc}") from exc
        if task.id in seen:
            raise DatasetError(f"{file}:{number}: duplicate task id {task.id!r}")
        seen.add(task.id)
        tasks.append(task)
    if not tasks:
        raise DatasetError(f"{file}: no tasks")
    return tasks


def dump_tasks(tasks: Iterable[Task]) -> str:
    """The file text: one compact JSON object per line, fields in a stable order."""
    return "".join(
        json.dumps(t.model_dump(mode="json", exclude_none=True), ensure_ascii=False) + "\n"
        for t in tasks
    )


def office_for_tasks(tasks_path: str | Path) -> Path | None:
    """An ``office.yaml`` beside the task file, if there is one."""
    candidate = Path(tasks_path).resolve().parent / "office.yaml"
    return candidate if candidate.is_file() else None
