"""A paper or file "for <Capitalised name>" nobody in the office has is what it is about, not
whom it is for, where the name ends in the noun of a place or firm or where the message names
the colleague who gets it (fix154b, class 3; ``reading.paper_topic``); a name alone is still
asked, and a colleague's name still receives."""

from __future__ import annotations

import pytest
from _offices import parser, tasks_of

from helpers.kit_station import kit_station
from helpers.reading import frame_reader

_station = frame_reader(kit_station, "callum")


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        # the class's own shape, on a station whose pre-plans are files to print
        (
            "Print off the pre-plan for Kestrel Mills and give it to Eilidh before the drill",
            ("print", "plan_file", "callum", "eilidh"),
        ),
        # variants: another firm, a street, a name beside the colleague who gets it
        (
            "print the quote for Riverside House and give it to Fraser",
            ("print", "plan_file", "callum", "fraser"),
        ),
        ("print my pre-plan for Harbour Road", ("print", "plan_file", "callum", "callum")),
        (
            "print my pre-plan for Kestrel and pass it to Morag",
            ("print", "plan_file", "callum", "morag"),
        ),
        ("copy the invoice for Acme Ltd for Morag", ("copy", "form", "callum", "morag")),
    ],
)
def test_the_outside_name_says_what_the_paper_is_about(
    text: str, expected: tuple[str, str, str, str]
) -> None:
    frame = _station(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [expected], frame


@pytest.mark.parametrize(
    ("office", "requester", "text", "expected"),
    [
        (
            "default",
            "zhou",
            "print my file for Riverside House and give it to Wang",
            [("print", "file", "zhou", "wang")],
        ),
        ("default", "zhou", "print my file for Kestrel Mills", [("print", "file", "zhou", "zhou")]),
        (
            "default",
            "zhou",
            "copy the invoice for Acme Ltd for Zhang",
            [("copy", "document", "zhou", "zhang")],
        ),
        (
            "harbour",
            "may",
            "print my file for Kestrel Mills and give it to Will",
            [("print", "file", "may", "will")],
        ),
    ],
)
def test_the_same_on_the_dataset_offices(
    office: str, requester: str, text: str, expected: list[tuple[str, str, str, str]]
) -> None:
    assert tasks_of(office, text, requester) == expected


def test_an_unknown_thing_for_a_firm_asks_what_it_is_not_who_the_firm_is() -> None:
    frame = parser("default").parse(
        "print the quote for Riverside House and give it to Wang", "zhou"
    )
    assert frame.question is not None and "Riverside" not in frame.question, frame


# -- must not change: a colleague's name receives; a name alone is asked ---------------------
def test_a_colleague_after_for_still_gets_it() -> None:
    assert tasks_of("default", "print my file for Wang", "zhou") == [
        ("print", "file", "zhou", "wang")
    ]
    frame = _station("print my pre-plan for Eilidh")
    assert [t.recipient for t in frame.tasks] == ["eilidh"], frame


@pytest.mark.parametrize(
    ("office", "requester", "text", "name"),
    [
        ("default", "zhou", "print my file for Kestrel", "Kestrel"),
        ("harbour", "may", "print my file for Riverside", "Riverside"),
    ],
)
def test_a_name_alone_is_still_asked(office: str, requester: str, text: str, name: str) -> None:
    frame = parser(office).parse(text, requester)
    assert frame.question == f"I don't know anyone called {name!r} in this office. Who do you mean?"


def test_an_ordinary_thing_for_a_firm_is_still_asked() -> None:
    frame = _station("bring my helmet for Kestrel Mills")
    assert frame.tasks == [] and frame.question is not None, frame
