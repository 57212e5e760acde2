"""A bare alias that is another colleague's family name is asked about, never taken silently:
with Morgan Tallis (called "Morgan") beside Priya Morgan (called "Inspector Morgan"), "take my
overtime form to Morgan" asks "Who do you mean by 'Morgan': Morgan Tallis or Priya Morgan?"
(names, no ids) and the answer says to whom it goes. The full name, the other's titled alias,
a title of address with the family name, the given name with the family name's initial, or
the other's given name decide it without a question. In either order of names (harbour
English, the default office family name first: Lin Tao called "Tao" beside Tao Hao), and the
dataset offices keep their readings ("Wang" is Wang Fang; "Liu", Liu Yang's alias and his own
family name, is him)."""

from __future__ import annotations

import pytest

from assistantx.core.task_schema import TaskFrame
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import ReadFrame, answered_reader, frame_reader
from helpers.renamed_offices import (
    default_with_two_taos,
    harbour_with_grants,
    harbour_with_morgans,
)

_MORGAN = "Who do you mean by 'Morgan': Morgan Tallis or Priya Morgan?"
_morgans = frame_reader(harbour_with_morgans, "may")
_morgans_answered = answered_reader(harbour_with_morgans, "may")
_taos = frame_reader(default_with_two_taos, "lee")
_grants = frame_reader(harbour_with_grants, "may")


def test_an_unranked_family_name_yields_to_the_given_name() -> None:
    # Lucía Grant has no rank before her family name: "Grant" alone is Grant Osei, as
    # colleagues of an English-named office speak (``given_name_meant``); Morgan stays asked
    # because Priya Morgan is "Inspector Morgan"
    assert _recipients(_grants("give my file to Grant")) == ["ray"]
    assert _recipients(_grants("give my file to Ms Grant")) == ["faith"]


def _recipients(frame: TaskFrame) -> list[str | None]:
    assert frame.question is None and frame.decline is None, frame
    return [t.recipient for t in frame.tasks]


@pytest.mark.parametrize(
    "text",
    [
        "can you take my overtime form to Morgan",  # the class
        "drop my file with Morgan please",
        "could you pass my document on to Morgan, she's expecting it",
        "Morgan needs a calculator",
    ],
)
def test_the_shared_word_is_asked(text: str) -> None:
    frame = _morgans(text)
    assert frame.tasks == [] and frame.question == _MORGAN, frame
    assert "bill" not in frame.question and "jack" not in frame.question  # no ids


@pytest.mark.parametrize(
    ("reader", "text", "asked"),
    [
        (_taos, "take my document to Tao", "Who do you mean by 'Tao': Tao Hao or Lin Tao?"),
        (_taos, "Tao needs a stapler", "Who do you mean by 'Tao': Tao Hao or Lin Tao?"),
    ],
)
def test_in_either_order_of_names(reader: ReadFrame, text: str, asked: str) -> None:
    frame = reader(text)
    assert frame.tasks == [] and frame.question == asked, frame


@pytest.mark.parametrize(
    ("answer", "who"),
    [
        ("Morgan Tallis", "bill"),
        ("Tallis", "bill"),
        ("Morgan T", "bill"),
        ("Priya Morgan", "jack"),
        ("Priya", "jack"),
        ("Inspector Morgan", "jack"),
    ],
)
def test_the_answer_delivers_to_the_one_chosen(answer: str, who: str) -> None:
    frame = _morgans_answered("can you take my overtime form to Morgan", [answer])
    assert _recipients(frame) == [who]


@pytest.mark.parametrize(
    ("text", "who"),
    [
        ("give my file to Inspector Morgan", "jack"),  # the other's titled alias
        ("give my file to Ms Morgan", "jack"),  # a title goes with the family name
        ("give my file to Priya Morgan", "jack"),
        ("give my file to Priya", "jack"),
        ("give my file to Morgan Tallis", "bill"),
        ("give my file to Morgan T", "bill"),  # the given name and the family's initial
        ("give my file to Tallis", "bill"),
    ],
)
def test_what_decides_it_is_not_asked(text: str, who: str) -> None:
    assert _recipients(_morgans(text)) == [who]


@pytest.mark.parametrize(
    ("reader", "text", "who"),
    [
        (_taos, "take my document to Mr Tao", "dang"),
        (_taos, "take my document to Lin Tao", "lin"),
        (_taos, "take my document to Hao", "dang"),
        (_grants, "give my file to Lucía", "faith"),
        (_grants, "give my file to Grant O", "ray"),
    ],
)
def test_what_decides_it_in_other_offices(reader: ReadFrame, text: str, who: str) -> None:
    assert _recipients(reader(text)) == [who]


@pytest.mark.parametrize(
    ("text", "who"),
    [
        ("take my document to Wang", "wang"),  # a family name nobody is called by bare
        ("give my book to Liu", "liu"),  # an alias that is its bearer's own family name
        ("give my book to Lee", "lee"),
        ("give my book to Mr Yang", "yang"),  # a title goes with the family name, as before
    ],
)
def test_default_office_must_not_change(text: str, who: str) -> None:
    assert _recipients(frame_reader(default_office, "sun")(text)) == [who]


def test_default_office_a_name_two_share_is_still_asked() -> None:
    frame = frame_reader(default_office, "lee")("give my book to Yang")
    assert frame.question == "Who do you mean by 'Yang': Liu Yang or Yang Lei?", frame


@pytest.mark.parametrize(
    ("text", "who"),
    [("give my file to Bill", "bill"), ("give my file to Dr Huang", "grace")],
)
def test_harbour_must_not_change(text: str, who: str) -> None:
    assert _recipients(frame_reader(harbour_office, "may")(text)) == [who]
