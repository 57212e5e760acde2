"""A colleague's want said with a helping verb ("Zhang would like a stapler", "Zhang'd like
a stapler", "Zhang could use a stapler", "Zhang could do with ...") is read as "Zhang wants"
(``reading.named_want``): the named colleague's need, restated and asked before anything
moves, never the speaker's want (a stapler borrowed for the speaker) nor request wording (a
stapler brought at once)."""

from __future__ import annotations

import pytest
from _offices import parser

from assistantx.agents.symbolic.reading.parser import InstructionParser
from helpers.field_centre import field_centre
from helpers.reading import frame_reader
from helpers.staff_room import staff_room


@pytest.mark.parametrize(
    ("name", "who", "text", "question"),
    [
        # the class's analogues
        ("default", "wu", "Zhang would like a stapler", "a stapler to Zhang Wei"),
        ("default", "wu", "Zhang'd like a stapler", "a stapler to Zhang Wei"),
        ("default", "wu", "Zhang could use a stapler", "a stapler to Zhang Wei"),
        ("default", "wu", "Zhang could do with a stapler", "a stapler to Zhang Wei"),
        # other people, other things, other offices
        ("default", "mao", "Wang would love a stapler", "a stapler to Wang Fang"),
        ("default", "mao", "Wang’d like some scissors", "a pair of scissors to Wang Fang"),
        ("harbour", "will", "Rose would like an umbrella", "an umbrella to Rose Adeyemi"),
        ("harbour", "will", "Mark'd like a ruler", "a ruler to Mark Lindqvist"),
        ("harbour", "will", "Mark could use a ruler", "a ruler to Mark Lindqvist"),
        # asked of a name: the same want, put as a question
        ("default", "wu", "would Zhang like a stapler?", "a stapler to Zhang Wei"),
        ("harbour", "will", "would Rose like an umbrella?", "an umbrella to Rose Adeyemi"),
        # must not change: the forms already read as the colleague's need
        ("default", "wu", "Zhang needs a stapler", "a stapler to Zhang Wei"),
        ("default", "wu", "Zhang wants a stapler", "a stapler to Zhang Wei"),
        ("default", "wu", "Zhang is after a stapler", "a stapler to Zhang Wei"),
    ],
)
def test_a_named_want_is_that_persons_need(name: str, who: str, text: str, question: str) -> None:
    frame = parser(name).parse(text, who)
    assert not frame.tasks and frame.question == f"Shall I bring {question}?", frame


@pytest.mark.parametrize(
    ("name", "who", "text"),
    [
        # must not change: the speaker's own want is fetched for the speaker
        ("default", "wu", "I would like a stapler"),
        ("default", "wu", "I'd like a stapler"),
        ("harbour", "will", "I could use a ruler"),
    ],
)
def test_the_speakers_own_want_is_theirs(name: str, who: str, text: str) -> None:
    frame = parser(name).parse(text, who)
    assert frame.tasks and frame.question is None, frame
    assert all(t.recipient in (None, who) for t in frame.tasks), frame


@pytest.mark.parametrize(
    ("name", "who", "text", "recipient"),
    [
        # with request wording after it, the named colleague receives at once
        ("default", "wu", "Zhang would like a stapler, could you bring him one", "zhang"),
        ("harbour", "will", "Rose could use an umbrella, please bring her one", "rose"),
    ],
)
def test_a_named_want_with_a_request_goes_to_them(
    name: str, who: str, text: str, recipient: str
) -> None:
    frame = parser(name).parse(text, who)
    assert frame.tasks and all(t.recipient == recipient for t in frame.tasks), frame


def test_a_want_of_work_is_read_as_before() -> None:
    # "Zhang would like you to print my file": no thing wanted after the phrase, left as said
    frame = parser("default").parse("Zhang would like you to print my file", "wu")
    assert frame.tasks and all(t.recipient != "zhang" for t in frame.tasks), frame


_staff_room = frame_reader(staff_room, "ravi")


@pytest.mark.parametrize(
    ("said", "question"),
    [
        # moved from test_named_recipient: restated as "Tam needs a coffee" is
        ("Tam could do with a coffee", "Shall I get coffee for Tam Rees?"),
        ("Tam needs a coffee", "Shall I get coffee for Tam Rees?"),
    ],
)
def test_a_small_offices_named_want_is_asked(said: str, question: str) -> None:
    frame = _staff_room(said)
    assert not frame.tasks and frame.question == question, frame


def test_a_field_centre_named_want_is_asked() -> None:
    # moved from test_round17_reader_classes: restated as "Linh needs a hole punch" is
    frame = InstructionParser(field_centre()).parse("Linh could do with a hole punch", "bea")
    assert not frame.tasks and frame.question == "Shall I bring a hole punch to Linh Vo?", frame
