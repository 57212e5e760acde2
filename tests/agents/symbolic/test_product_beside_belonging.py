"""One verb with two objects joined by "and": an unlisted thing asked for from a facility ("a
coke from the vending machine", the machine makes one product of that kind) beside a
colleague's thing (blind round 69's class). The facility's thing was dropped when the frames
read the colleague's thing; now it is the facility's product, as when it is asked for alone,
and both go to the speaker. A thing of no kind the facility makes is never swapped."""

from __future__ import annotations

import pytest

from assistantx.core.task_schema import Task
from helpers.dataset_offices import default_office
from helpers.reading import frame_reader

_frame = frame_reader(default_office, "lee")


@pytest.mark.parametrize(
    ("text", "owner", "item"),
    [
        ("grab me a coke from the vending machine and Wang's stapler", "wang", "stapler"),
        ("get me a lemonade from the vending machine and Zhang's scissors", "zhang", "scissors"),
        ("could you grab me a coke from the snack machine and Wang's stapler", "wang", "stapler"),
        ("get me Wang's stapler and a coke from the vending machine", "wang", "stapler"),
        (
            "bring me a lemonade from the vending machine and also Zhang's scissors pls",
            "zhang",
            "scissors",
        ),
    ],
)
def test_the_facilitys_variety_and_the_colleagues_thing_are_both_delivered(
    text: str, owner: str, item: str
) -> None:
    frame = _frame(text)
    assert frame.question is None and frame.decline is None, frame
    assert Task(kind="produce", item="snack", recipient="lee") in frame.tasks, frame
    assert any(
        t.kind == "transfer" and t.item == item and t.owner == owner and t.recipient == "lee"
        for t in frame.tasks
    ), frame
    assert len(frame.tasks) == 2, frame


@pytest.mark.parametrize(
    ("text", "items"),
    [
        # near misses: known products and a colleague's thing, as before
        ("get me a coffee from the coffee machine and Wang's stapler", {"coffee", "stapler"}),
        ("grab me a snack from the vending machine and Wang's stapler", {"snack", "stapler"}),
        ("grab me Wang's stapler and a chocolate bar", {"stapler", "snack"}),
        ("get me a coke from the vending machine", {"snack"}),
    ],
)
def test_known_products_read_as_before(text: str, items: set[str]) -> None:
    frame = _frame(text)
    assert {t.item for t in frame.tasks} == items, frame


def test_a_thing_of_no_kind_the_facility_makes_is_never_swapped() -> None:
    frame = _frame("grab me some chloroform from the vending machine and Wang's stapler")
    assert all(t.item != "snack" for t in frame.tasks), frame
    assert "no coke" in (_frame("grab me a coke").decline or ""), "a coke said alone: declined"
