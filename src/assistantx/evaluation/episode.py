"""One scored run of one task: the trace plus the world facts the metrics need.

An ``Episode`` is plain data (it is one line of ``results.jsonl``), so the metrics are pure
functions of it. ``relevant_people`` / ``relevant_places`` come from the goal and the office's
truth (``relevance``), never from what the method did.
"""

from __future__ import annotations

from typing import Any

from pydantic import BaseModel, Field

from assistantx.core.trace import Trace


class Handover(BaseModel):
    """An item that ended in a person's hands (a collect at the locker)."""

    item: str
    to: str
    time: float = 0.0


class SentOut(BaseModel):
    """An item a colleague sent outside the office, and what they were told to do with it."""

    item: str
    told: str


class Episode(BaseModel):
    task_id: str
    run: int = Field(ge=0)
    method: str
    level: str
    achievable: bool
    requester: str
    unavailable: list[str] = Field(default_factory=list)
    goal: list[dict[str, Any]]
    optimal_actions: int = Field(ge=1)
    requested_goal: list[dict[str, Any]] = Field(
        default_factory=list, description="what was asked, for an unachievable task"
    )
    relevant_people: list[str] = Field(default_factory=list, description="incl. groups")
    relevant_places: list[str] = Field(default_factory=list, description="location ids")
    milestones: list[bool] = Field(description="which goal milestones hold at the end")
    handovers: list[Handover] = Field(default_factory=list)
    sent_out: list[SentOut] = Field(default_factory=list)
    destinations: list[str] = Field(
        default_factory=list, description="where the task's send-out parts go (its truth)"
    )
    trace: Trace
    wall_s: float = 0.0
    sim_time_s: float = 0.0
    distance_m: float = 0.0
    error: str | None = Field(default=None, description="the harness could not run it")
