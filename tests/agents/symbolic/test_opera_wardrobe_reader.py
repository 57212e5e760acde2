"""Blind round 16's reader classes, on an opera house's wardrobe office built in the tests
(``helpers.opera_wardrobe``; the round's names are not used). Each class has its phrasings
and the near-misses that must not change: a reading the reader is unsure of is asked, never
acted on."""

from __future__ import annotations

import pytest

from assistantx.core.task_schema import TaskFrame
from helpers.opera_wardrobe import opera_wardrobe
from helpers.reading import answered_reader, frame_reader

_frame = frame_reader(opera_wardrobe, "ilse")
_answered = answered_reader(opera_wardrobe, "ilse")


def _moves(frame: TaskFrame) -> list[tuple[str, str | None, str | None, str]]:
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


# -- class 1: a room named as where an item is wanted is no request for the room's service ----


@pytest.mark.parametrize(
    "text",
    [
        "need a spirit level in the scene dock asap, hanging the flats",
        "could someone bring me a spirit level in the scene dock",
        "I need a level at the scene dock please",
    ],
)
def test_an_item_wanted_in_a_room_whose_service_nobody_runs_is_brought(text: str) -> None:
    frame = _frame(text, "bram")
    assert _moves(frame) == [("transfer", "spirit_level", None, "bram")]
    assert frame.question is None and frame.decline is None


@pytest.mark.parametrize(
    "text",
    ["could you rig the scene dock", "can you sort out the scene dock for me"],
)
def test_the_room_itself_asked_for_is_still_refused(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == []
    assert "can't help with the scene dock" in (frame.question or frame.decline or "")


def test_a_question_about_an_item_in_the_room_moves_nothing() -> None:
    assert _frame("is there a spirit level in the scene dock?").tasks == []


# -- class 2: a facility said to have some is where the supply is, not its service asked ------


@pytest.mark.parametrize(
    "text",
    [
        "need PP3 batteries for the radio mics, goods door has some",
        "could you get me PP3 batteries, goods door has some",
        "need PP3s, goods door's got some",
        "need PP3 batteries, goods door should have a few",
    ],
)
def test_a_supply_said_to_be_at_a_facility_is_fetched_from_it(text: str) -> None:
    frame = _frame(text)
    assert _moves(frame) == [("transfer", "pp3_batteries", "goods_door", "ilse")]


def test_the_facility_s_own_service_is_still_asked_where_it_sends() -> None:
    frame = _frame("could you dry clean my gown at the goods door")
    assert frame.tasks == [] and "name of the cleaner" in (frame.question or "")


def test_a_question_whether_the_facility_has_some_moves_nothing() -> None:
    assert _frame("does the goods door have any PP3 batteries?").tasks == []


# -- class 3: a send-out's destination is a place named, never "to be done" or the kind ------

_WHERE = "Please give me the name of the cleaner."


@pytest.mark.parametrize(
    "text",
    [
        "Send my gown to Harlow Cleaners to be dry cleaned please.",
        "send my gown off to Harlow Cleaners",
        "could you send my gown off to Harlow Cleaners to be dry cleaned",
    ],
)
def test_a_named_cleaner_is_where_the_gown_is_sent(text: str) -> None:
    frame = _frame(text)
    assert [(t.operation, t.item, t.owner, t.destination) for t in frame.tasks] == [
        ("dryclean", "gown", "ilse", "Harlow Cleaners")
    ]


@pytest.mark.parametrize(
    "text",
    [
        "Could you have my gown sent off to be dry cleaned? The wine stain won't come out.",
        "can you send my gown off to the cleaner",
        "can you send my gown off to the cleaners please",
        "could you get my gown dry cleaned",
    ],
)
def test_no_cleaner_named_is_asked_never_guessed(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and _WHERE in (frame.question or "")
    answered = _answered(text, ["Harlow Cleaners"])
    assert [(t.operation, t.destination) for t in answered.tasks] == [
        ("dryclean", "Harlow Cleaners")
    ]


def test_an_answer_that_names_the_work_again_is_no_place() -> None:
    text = "could you have my gown sent off to be dry cleaned?"
    frame = _answered(text, ["To be dry cleaned, the stain won't come out."])
    assert frame.tasks == [] and _WHERE in (frame.question or "")


def test_a_question_about_the_cleaners_moves_nothing() -> None:
    assert _frame("has my gown come back from the cleaners yet?").tasks == []


# -- class 4: "a shake" after an article is the thing a make-from-nothing service makes -------


@pytest.mark.parametrize(
    ("text", "recipient"),
    [
        ("could you make me a shake? been on my feet all day", "ilse"),
        ("could you get me a shake", "ilse"),
        ("can you whip up a shake for Bram", "bram"),
        ("could you shake me a milkshake", "ilse"),
    ],
)
def test_a_product_named_by_its_service_s_verb_is_made(text: str, recipient: str) -> None:
    assert _moves(_frame(text)) == [("produce", "milkshake", None, recipient)]


@pytest.mark.parametrize(
    "text",
    ["thanks for the shake", "I don't want a shake, thanks", "is the shake bar open?"],
)
def test_thanks_refusals_and_questions_about_it_move_nothing(text: str) -> None:
    assert _frame(text).tasks == []


# -- class 5: "mine" as the subject of a clause is the reason, never the item asked for ------


@pytest.mark.parametrize(
    "text",
    [
        "can i borrow Bram's seam ripper? mine have gone blunt",
        "can i borrow Bram's seam ripper? mine are at home",
        "could I borrow Bram's seam ripper, mine's broken",
        "can I have a lend of Bram's seam ripper? mine were left at home",
    ],
)
def test_mine_as_a_subject_leaves_the_borrowing_as_asked(text: str) -> None:
    frame = _frame(text)
    assert _moves(frame) == [("transfer", "seam_ripper", "bram", "ilse")]
    assert frame.question is None


@pytest.mark.parametrize(
    "text",
    [
        "Gwen needs a seam ripper, can you take mine to her",
        "Gwen wants a seam ripper, take mine over to her please",
    ],
)
def test_mine_as_an_object_is_still_my_item(text: str) -> None:
    assert _moves(_frame(text)) == [("transfer", "seam_ripper", "ilse", "gwen")]
