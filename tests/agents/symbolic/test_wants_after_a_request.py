"""Fixer fix59h class 1: someone's want said after a complete request is its reason.

A sentence after a request whose subject is an outsider (a reader, a visitor, a client) or the
request's own recipient, saying what they want or want to do ("a reader wants a photo of the
display case", "she wants to go through the invoices"), says why the request is made: nothing
it names is fetched or asked about (``screen.recipients_doing``). Before, the photo (a
colleague's photograph) was fetched beside the camera, and "the invoices" (a document's
synonym) was handed over or asked about beside the printout.

Unchanged: a colleague's want ("Zhang wants a pen too": a second request), a second need of the
recipient ("He also needs my stapler"), an addition ("a visitor wants a coffee too"), and an
outsider's want said alone ("a visitor wants a coffee")."""

from __future__ import annotations

import pytest
from _offices import parser

from helpers import office_builder as ob
from helpers.reading import frame_reader

_PEOPLE = (
    ob.person("ines", "Ines Moreau", "lab_book"),
    ob.person("omar", "Omar Said", "photograph", "stapler", aliases=["Omar"]),
    ob.person("kai", "Kai Lund", "ruler", aliases=["Kai"]),
)


def _raw() -> ob.Row:
    return ob.office_file(
        "archive room",
        _PEOPLE,
        rooms=[ob.room("store", "Store room", 12.0, 20.0)],
        item_types=[
            ob.item("lab_book", "lab book", "personal"),
            ob.item("photograph", "photograph", "personal", synonyms=["photo", "picture"]),
            {**ob.item("camera", "camera"), "purposes": ["take photos"]},
            ob.item("ruler", "ruler"),
            ob.item("stapler", "stapler"),
        ],
        operations=[],
        facilities=[],
        home="store",
    )


_archive = frame_reader(ob.parsed(_raw), "ines")


def _tasks(frame: object) -> list[tuple[str, str | None, str | None, str]]:
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]  # type: ignore[attr-defined]


@pytest.mark.parametrize(
    "text",
    [
        "Could you borrow a camera for me? A reader wants a photo of the display case.",
        "can you get me a camera? a client wants some photos of the stand",
        "Could you bring me a camera? A visitor wants to take a photo of the poster",
    ],
)
def test_an_outsiders_want_after_a_request_is_its_reason(text: str) -> None:
    frame = _archive(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("transfer", "camera", "ines")
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        "Could you bring me a stapler? A visitor wants to check the invoices",
        "Could you bring me a stapler? A visitor wants to pin up a poster",
        "Could you bring me scissors? A client wants a book to read",
    ],
)
def test_an_outsiders_want_in_the_default_office(text: str) -> None:
    frame = parser("default").parse(text, "lee")
    assert frame.question is None and frame.decline is None, frame
    assert len(frame.tasks) == 1 and frame.tasks[0].recipient == "lee", frame
    assert frame.tasks[0].item in ("stapler", "scissors"), frame


@pytest.mark.parametrize(
    ("text", "kind", "item"),
    [
        (
            "print my report and take it to Zhang, he wants to go through the invoices",
            "print",
            "file",
        ),
        (
            "copy my form and give the copy to Wang, she wants to check the invoices",
            "copy",
            "document",
        ),
    ],
)
def test_the_recipients_want_after_a_made_thing_is_its_reason(
    text: str, kind: str, item: str
) -> None:
    frame = parser("default").parse(text, "lee")
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.owner) for t in frame.tasks] == [(kind, item, "lee")], frame


def test_the_recipients_want_in_harbour() -> None:
    frame = parser("harbour").parse(
        "could you print my file and give the hard copy to Hope? she wants to go through the "
        "invoices",
        "may",
    )
    assert frame.question is None and frame.decline is None, frame
    assert _tasks(frame) == [("print", "file", "may", "hope")], frame


# -- must not change ---------------------------------------------------------------------


def test_a_colleagues_want_is_a_second_request() -> None:
    frame = parser("default").parse("Could you bring me a stapler? Zhang wants a pen too", "lee")
    assert [(t.item, t.recipient) for t in frame.tasks] == [("stapler", "lee"), ("pen", "zhang")]


def test_the_recipients_second_need_is_a_second_request() -> None:
    frame = parser("default").parse(
        "print my report and take it to Zhang. He also needs my stapler", "lee"
    )
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("print", "file", "zhang"),
        ("transfer", "stapler", "zhang"),
    ], frame


def test_an_outsiders_want_added_is_read_as_before() -> None:
    frame = parser("default").parse(
        "Could you bring me a stapler? A visitor wants a coffee too", "lee"
    )
    assert [t.item for t in frame.tasks] == ["stapler", "coffee"], frame


def test_an_outsiders_want_alone_is_asked_as_before() -> None:
    frame = parser("default").parse("a visitor wants a coffee", "lee")
    assert frame.tasks == [] and frame.question == "Shall I get coffee for you?", frame


def test_a_colleagues_photograph_asked_alone_is_still_fetched() -> None:
    frame = _archive("Could you bring me Omar's photo?")
    assert _tasks(frame) == [("transfer", "photograph", "omar", "ines")], frame


def test_the_recipients_want_of_the_speakers_thing_is_read_as_before() -> None:
    frame = parser("default").parse("Take my stapler to Zhang, he wants to sign my form", "lee")
    assert [t.item for t in frame.tasks] == ["stapler"], frame
