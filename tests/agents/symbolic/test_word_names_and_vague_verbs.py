"""Round 186's classes of the reader (analogues of outside testers' sentences, none of them),
on a tack room of our own (``helpers.tack_room``): asking a colleague named by a lower-case
surname to borrow "her thing for <purpose>", and "me" answered to who should get it; a
colleague's name that is also a describing word before a thing they own; a service said as
the thing going or being sent for it; a vague verb ("get it sorted") where the office has one
work on the thing. Each with neighbours whose reading must stay."""

from __future__ import annotations

import pytest

from assistantx.core.task_schema import TaskFrame, operation_of
from helpers.reading import answered_reader, frame_reader
from helpers.tack_room import tack_room

_frame = frame_reader(tack_room, "lee")
_answered = answered_reader(tack_room, "lee")

Row = tuple[str, str | None, str | None, str | None]


def _rows(frame: TaskFrame) -> list[Row]:
    assert frame.question is None and frame.decline is None, frame.question or frame.decline
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


# -- class 1: "ask bell if I can borrow her thing for ...", and "me" answered --------------

_ISLAS = [("transfer", "case_opener", "isla", "lee")]


@pytest.mark.parametrize(
    "text",
    [
        "ask bell if i can borrow her thing for opening cases this afternoon",
        "ask Isla if I can borrow her thing for opening cases",
        "can I borrow Isla's thing for opening cases",
        # must not change: the thing named, and the surname after "ask"
        "ask bell if i can borrow her case opener",
        "ask Isla if I can borrow her case opener",
    ],
)
def test_borrowing_a_colleagues_thing_said_by_its_purpose_is_hers_for_the_speaker(
    text: str,
) -> None:
    assert _rows(_frame(text)) == _ISLAS


def test_a_purpose_with_no_owner_said_is_still_anyones() -> None:
    assert _rows(_frame("I need something for opening cases")) == [
        ("transfer", "case_opener", None, "lee")
    ]


_TO_HER = "get Isla her case opener"


def test_the_colleagues_own_thing_to_herself_is_asked() -> None:
    assert _frame(_TO_HER).question == (
        "Isla Bell already has their case opener; who should get it?"
    )


@pytest.mark.parametrize("answer", ["Me.", "me please", "to me", "I do", "Me, thanks"])
def test_me_answered_to_who_should_get_a_colleagues_thing_is_the_requester(answer: str) -> None:
    assert _rows(_answered(_TO_HER, [answer])) == _ISLAS


@pytest.mark.parametrize("answer", ["Me.", "I do"])
def test_me_answered_to_who_should_get_your_own_thing_stays_the_requester(answer: str) -> None:
    assert _rows(_answered("bring my harness", [answer])) == [("transfer", "harness", "lee", "lee")]


def test_an_answer_that_is_no_one_leaves_it_asked() -> None:
    assert _answered(_TO_HER, ["not sure"]).tasks == []


# -- class 2: a colleague's name that is also a describing word, before a thing they own --

_AMBER = "bring me the amber accord from the cold room"
_WHICH_ACCORD = "Do you mean Amber Shaw's accord, or your own amber accord?"


@pytest.mark.parametrize("text", [_AMBER, "bring me the amber accord", "grab the amber accord"])
def test_a_name_word_before_a_thing_the_colleague_owns_is_asked(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question == _WHICH_ACCORD


@pytest.mark.parametrize("answer", ["Amber's", "hers", "Amber"])
def test_the_colleague_chosen_is_hers(answer: str) -> None:
    assert _rows(_answered("bring me the amber accord", [answer])) == [
        ("transfer", "accord", "amber", "lee")
    ]


@pytest.mark.parametrize("answer", ["mine", "my own one"])
def test_the_speakers_own_chosen_is_no_longer_asked_as_hers(answer: str) -> None:
    assert _answered("bring me the amber accord", [answer]).question != _WHICH_ACCORD


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        ("bring me amber's accord", "amber"),  # the possessive says whose
        ("bring me Amber's accord", "amber"),
    ],
)
def test_must_not_change_a_colleague_said_as_owner(text: str, owner: str) -> None:
    assert _rows(_frame(text)) == [("transfer", "accord", owner, "lee")]


def test_must_not_change_a_name_word_before_a_thing_the_colleague_lacks() -> None:
    # Amber has no harness: "amber" is only the word
    assert _frame("bring me the amber harness").question != (
        "Do you mean Amber Shaw's harness, or your own amber harness?"
    )


def test_must_not_change_the_speakers_own_said() -> None:
    assert "Amber Shaw" not in (_frame("bring me my amber accord").question or "")


# -- class 3: a service said as the thing going or sent for it -----------------------------

_INSPECTED = [("copy", "harness", "lee", "lee")]


@pytest.mark.parametrize(
    "text",
    [
        "can my harness go for inspection",
        "could my harness go in for an inspection please",
        "send my harness for inspection",
        "send my harness off for an inspection this afternoon",
        "lost all patience with this buckle tbh. can my harness go in for inspection",
        # must not change: said with its need
        "my harness needs inspection",
        "inspect my harness",
    ],
)
def test_a_thing_going_for_a_service_asks_for_the_service(text: str) -> None:
    frame = _frame(text)
    assert _rows(frame) == _INSPECTED
    assert [operation_of(tack_room(), t) for t in frame.tasks] == ["inspect"]


def test_must_not_change_a_thing_sent_to_a_colleague_for_a_service() -> None:
    assert _rows(_frame("send my harness to Tom for inspection")) == [
        ("transfer", "harness", "lee", "tom")
    ]


def test_must_not_change_a_thing_going_for_what_the_office_does_not_do() -> None:
    assert _frame("can my mug go for a wash").tasks == []


# -- class 4: a vague verb where the office has one work on the thing -----------------------

_SORTED = "can you get my costume sorted before the dress run"
_FETCH_OR_MEND = "Shall I bring you your costume, or have it mended?"


@pytest.mark.parametrize("text", [_SORTED, "see to my costume", "get my costume sorted"])
def test_a_vague_verb_on_a_thing_one_work_takes_asks_fetch_or_work(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question == _FETCH_OR_MEND


@pytest.mark.parametrize("answer", ["mended please", "have it mended", "mend it", "get it mended"])
def test_the_work_chosen_is_done(answer: str) -> None:
    frame = _answered(_SORTED, [answer])
    assert _rows(frame) == [("heat", "costume", "lee", "lee")]
    assert [operation_of(tack_room(), t) for t in frame.tasks] == ["mend"]


@pytest.mark.parametrize("answer", ["just bring it", "just get it"])
def test_bringing_chosen_is_no_work(answer: str) -> None:
    frame = _answered(_SORTED, [answer])
    assert frame.question != _FETCH_OR_MEND
    assert all(operation_of(tack_room(), t) is None for t in frame.tasks)


@pytest.mark.parametrize("text", ["can you get my mug sorted", "bring me my costume"])
def test_must_not_change_no_work_on_the_thing_or_no_vague_verb(text: str) -> None:
    assert _frame(text).question != _FETCH_OR_MEND
