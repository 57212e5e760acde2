"""Stage 4, frames: readings → the tasks (kind, item, owner, recipient, actor) or a question."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from assistantx.agents.symbolic.reading.frames import NOT_UNDERSTOOD, FrameReader
from assistantx.agents.symbolic.reading.lexicon import Lexicon
from assistantx.agents.symbolic.reading.readings import MentionReader
from assistantx.core.office import Office
from assistantx.core.task_schema import TaskFrame


@pytest.fixture(scope="module")
def frame(office: Office) -> Callable[[str], TaskFrame]:
    lex = Lexicon.from_office(office)
    readings, frames = MentionReader(office, lex), FrameReader(office)

    def framed(text: str, requester: str = "lee") -> TaskFrame:
        return frames.frame(readings.read(lex.read(text)), requester)

    return framed


def test_a_clause_with_no_task_of_its_own_fills_in_the_one_before(
    frame: Callable[[str], TaskFrame],
) -> None:
    (task,) = frame("print my report and take it to Wang").tasks  # one errand, not two
    assert (task.kind, task.owner, task.recipient) == ("print", "lee", "wang")


def test_each_coordinated_object_is_a_task_of_its_own(frame: Callable[[str], TaskFrame]) -> None:
    tasks = frame("bring me a stapler and some scissors").tasks
    assert [(t.kind, t.item, t.recipient) for t in tasks] == [
        ("transfer", "stapler", "lee"),
        ("transfer", "scissors", "lee"),
    ]


def test_roles_come_from_the_words_around_each_person(frame: Callable[[str], TaskFrame]) -> None:
    (task,) = frame("bring Zhang Wei's stapler to Hu Jing").tasks
    assert (task.kind, task.item, task.owner, task.recipient) == (
        "transfer",
        "stapler",
        "zhang",
        "hu",
    )


def test_a_doubt_from_the_readings_is_asked_and_no_task_is_made(
    frame: Callable[[str], TaskFrame],
) -> None:
    framed = frame("bring me Zhnag's stapler")
    assert framed.tasks == [] and framed.question is not None and "Zheng Hui" in framed.question


def test_a_text_with_no_request_asks_what_is_needed(frame: Callable[[str], TaskFrame]) -> None:
    assert frame("hello there").question == NOT_UNDERSTOOD


@pytest.mark.parametrize(
    "text", ["could you heat something up for me?", "can you warm one up for me please"]
)
def test_a_service_with_no_item_asks_which_item_in_plain_words(
    frame: Callable[[str], TaskFrame], text: str
) -> None:
    framed = frame(text)
    # the person reads the question: never a task kind's id ("the heat request")
    assert framed.tasks == []
    assert framed.question == "Which item do you mean for me to heat?"
