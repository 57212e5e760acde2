"""Fix115d, class 1 (analogues, not the measured sentences): a send-out's destination said as
a place outside. Three mechanisms: the words a service's name says before its means may be
said before it too ("with the *interlibrary* courier", reading/destination.means_modifiers);
capitalised words then the head noun of a kind of place ("Westgate branch", "the Northfield
depot") name a place, so a plain "send" to it sends out and an address goes on past its comma
(reading/named_place.py); and a comma part in title case ("..., King's Building") is a name
said on, never a statement of its own (reading/screen/title_cased_part.py). A colleague's
name, or a bare unknown name, is read as before: asked, never a wrong person."""

from __future__ import annotations

import functools

import pytest

from assistantx.core.task_schema import TaskFrame
from helpers.dataset_offices import default_office_that_sends_out, harbour_that_posts
from helpers.library_courier import library_courier
from helpers.reading import frame_reader

_library = frame_reader(library_courier, "mao")
_default = frame_reader(
    functools.partial(
        default_office_that_sends_out, "courier", "send by courier", "courier", "the address"
    ),
    "mao",
)
_harbour = frame_reader(harbour_that_posts, "may")


def _sent(frame: TaskFrame, operation: str) -> list[str | None]:
    assert frame.question is None, frame.question
    return [t.destination for t in frame.tasks if t.operation == operation]


@pytest.mark.parametrize(
    ("text", "destination"),
    [
        # the class's analogue: the service's own modifier before its means
        (
            "Please send my book to Westgate branch with the interlibrary courier",
            "Westgate branch",
        ),
        (
            "send my book to the Northfield depot via the interlibrary courier",
            "the Northfield depot",
        ),
        (
            "can you send my novel to Eastgate campus with the interlibrary courier please",
            "Eastgate campus",
        ),
        # a plain "send" to a named place: the one send-out service that takes a book
        ("send my book to Westgate branch", "Westgate branch"),
        ("send my book to the Northfield depot", "the Northfield depot"),
        # the address goes on past a named place's comma
        ("courier my book to Eastgate campus, Room 12", "Eastgate campus, Room 12"),
        ("send my book to Westgate branch, Library Lane please", "Westgate branch, Library Lane"),
    ],
)
def test_a_named_place_is_the_librarys_destination(text: str, destination: str) -> None:
    assert _sent(_library(text), "courier") == [destination]


@pytest.mark.parametrize(
    ("text", "destination"),
    [
        (
            "courier my contract to Dr Okafor, School of Pharmacy, King's Building",
            "Dr Okafor, School of Pharmacy, King's Building",
        ),
        (
            "courier my report to Prof Adeyemi, Department of Chemistry, Roscoe Building, "
            "Oxford Road",
            "Prof Adeyemi, Department of Chemistry, Roscoe Building, Oxford Road",
        ),
        ("courier my contract to Eastgate campus, Room 12", "Eastgate campus, Room 12"),
    ],
)
def test_every_address_part_is_the_destination(text: str, destination: str) -> None:
    assert _sent(_default(text), "courier") == [destination]


@pytest.mark.parametrize(
    ("text", "destination"),
    [
        ("send my letter to the Northfield depot", "the Northfield depot"),
        ("post my contract to Eastgate campus, Room 12", "Eastgate campus, Room 12"),
        (
            "post my contract to Dr Adeyemi, School of Pharmacy, King's Building",
            "Dr Adeyemi, School of Pharmacy, King's Building",
        ),
    ],
)
def test_harbour_posts_to_a_named_place(text: str, destination: str) -> None:
    assert _sent(_harbour(text), "frank") == [destination]


def test_no_place_said_is_still_asked() -> None:
    frame = _library("send my book with the interlibrary courier")
    assert frame.tasks == []
    assert frame.question is not None and frame.question.startswith("Where should I courier")


# -- must not change ---------------------------------------------------------------------


def test_a_colleague_with_the_courier_is_asked_which() -> None:
    frame = _library("send my book to Wang with the courier")
    assert frame.tasks == []
    assert frame.question == (
        "Should I send it out by courier to Wang outside the office, or bring it to Wang Fang here?"
    )


@pytest.mark.parametrize(
    ("read", "text", "recipient"),
    [(_library, "send my book to Wang", "wang"), (_harbour, "send my contract to Mark", "mark")],
)
def test_a_plain_send_to_a_colleague_is_a_hand_over(
    read: object, text: str, recipient: str
) -> None:
    frame = read(text)  # type: ignore[operator]
    assert [(t.kind, t.recipient, t.operation) for t in frame.tasks] == [
        ("transfer", recipient, None)
    ]


@pytest.mark.parametrize(
    ("read", "text"),
    [(_library, "send my book to Westgate"), (_harbour, "send my contract to Westgate")],
)
def test_a_bare_unknown_name_is_asked_never_a_person(read: object, text: str) -> None:
    frame = read(text)  # type: ignore[operator]
    assert frame.tasks == []
    assert frame.question is not None and "'Westgate'" in frame.question


def test_a_sentence_cased_clause_after_a_comma_is_still_its_own() -> None:
    # "Sun is building ..." is a clause in sentence case: a statement, not the address
    assert _sent(
        _default("courier my contract to Ofcom, Sun is building the shelves"), "courier"
    ) == ["Ofcom"]
