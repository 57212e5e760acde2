"""The feedback part of the service, built by the runtime's start like every other component:
the survey tables in the journal's SQLite file and the Surveyor attached to the Assistant
(surveys after each instruction, replies taken before a direct message becomes an
instruction, reminders every minute)."""

from __future__ import annotations

import asyncio
import logging
from contextlib import AsyncExitStack
from dataclasses import dataclass
from pathlib import Path

from assistantx.adapters.robot.navigator import NavigatorRobot
from assistantx.core.clock import Clock
from assistantx.core.errors import AssistantXError
from assistantx.core.office import Office
from assistantx.feedback.store import FeedbackStore
from assistantx.feedback.surveyor import Surveyor
from assistantx.feedback.walking import DistanceFn, over_map
from assistantx.runtime.assistant import Assistant

logger = logging.getLogger(__name__)


@dataclass(frozen=True)
class FeedbackParts:
    store: FeedbackStore
    surveyor: Surveyor


def map_distance(
    office: Office, clock: Clock, map_yaml: Path, anchors_yaml: Path | None
) -> DistanceFn | None:
    """Walks over the office map's planner; straight lines when the map cannot be loaded."""
    try:
        robot = NavigatorRobot.from_files(
            office, clock, map_yaml=map_yaml, anchors_yaml=anchors_yaml, localize=False
        )
    except (AssistantXError, OSError) as exc:
        logger.warning("walking saved in straight lines: the office map is unusable (%s)", exc)
        return None
    return over_map(robot)


async def start_feedback(
    stack: AsyncExitStack,
    *,
    assistant: Assistant,
    journal_file: Path,
    database_url: str | None = None,
    map_yaml: Path,
    anchors_yaml: Path | None,
) -> FeedbackParts:
    """Open the survey store and start the Surveyor on ``assistant``; both stop with
    ``stack`` (the Surveyor first)."""
    office, clock = assistant.parts.office, assistant.clock
    store = FeedbackStore.open(journal_file, database_url=database_url)
    stack.callback(store.close)
    distance = await asyncio.to_thread(map_distance, office, clock, map_yaml, anchors_yaml)
    # Surveys go where the assistant talks to people (Matrix when configured).
    surveyor = Surveyor(office, store, assistant.parts.messenger, clock, distance=distance)
    surveyor.attach(assistant)
    await surveyor.start()
    stack.push_async_callback(surveyor.stop)
    return FeedbackParts(store, surveyor)
