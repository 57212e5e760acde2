"""The simulated requester says yes to a right restatement whose word for the wanted item
also names another item of the office (blind rounds 57-58's class: asked "Shall I print your
file for Wren?" by a requester who wanted a printout of their worksheet for Wren, it said "No,
thanks.": the office also keeps a stationery file, the offer's "file" was read as that, and an
offer naming an item the wish does not list is a no). A name the offer says that is also a
name of a wanted item (the electronic file the printout is made from) says nothing against
the wish; an offer of the other item by a name of its own ("a box file"), of an unrelated
item, or for someone else is still no."""

from __future__ import annotations

from typing import Any

import pytest

from assistantx.core.goals import Milestone
from assistantx.core.office import Office, parse_office
from assistantx.sim.requester import Wish, answer
from helpers import office_builder as ob
from helpers.cover_staff_room import raw_staff_room


def _with_a_box_file() -> Office:
    """The staff room with a box file, also called a file or a folder, listed first."""
    raw: dict[str, Any] = raw_staff_room()
    raw["item_types"].insert(0, ob.item("box_file", "box file", synonyms=["file", "folder"]))
    return parse_office(raw, raw["name"])


PRINTOUT_FOR_ADA: list[Milestone] = [
    {"printed": "worksheet:tess"},
    {"holds": ["ada", "printout:tess"]},
]
PRINTOUT_AND_STAPLER: list[Milestone] = [
    {"printed": "worksheet:tess"},
    {"holds": ["tess", "printout:tess"]},
    {"holds": ["tess", "stapler:colm"]},
]


def _says(goal: list[Milestone], question: str) -> str:
    office = _with_a_box_file()
    wish = Wish.from_goal(office, "tess", [*goal, {"informed": "tess"}])
    return answer(office, wish, question)


@pytest.mark.parametrize(
    ("goal", "question"),
    [
        (PRINTOUT_FOR_ADA, "Shall I print your file for Ada Okafor?"),
        (PRINTOUT_FOR_ADA, "Shall I print your worksheet for Ada Okafor?"),
        (PRINTOUT_FOR_ADA, "Shall I print off your file and take it to Ada Okafor?"),
        (
            PRINTOUT_AND_STAPLER,
            "Shall I print your file for you and bring Colm Brady's stapler to you?",
        ),
    ],
)
def test_a_right_restatement_gets_a_yes(goal: list[Milestone], question: str) -> None:
    assert _says(goal, question) == "Yes, please."


@pytest.mark.parametrize(
    ("goal", "question"),
    [
        (PRINTOUT_FOR_ADA, "Shall I print your file for Nils Lindqvist?"),
        (PRINTOUT_FOR_ADA, "Shall I bring Ada Okafor a box file?"),
        (PRINTOUT_FOR_ADA, "Shall I bring Ada Okafor a folder?"),
        (PRINTOUT_FOR_ADA, "Shall I print your file for Ada Okafor and bring her a hole punch?"),
        (PRINTOUT_AND_STAPLER, "Shall I print your file for you and bring you a box file?"),
    ],
)
def test_anything_else_gets_a_no(goal: list[Milestone], question: str) -> None:
    assert _says(goal, question) == "No, thanks."
