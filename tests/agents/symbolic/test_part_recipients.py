"""Each part of a combined request owns the recipient said inside its own stretch of text
(``reading/part_recipients``). "print my file and take it to wang, oh and a coffee for me"
handed the printout to the requester and the coffee to Wang, swapped: "take it to Wang"
belongs to the print, "for me" to the coffee. Tested on the default office and on harbour,
with other words than the class's, and beside neighbours that share one recipient."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "lee")
_harbour = frame_reader(harbour_office, "may")

Row = tuple[str, str | None, str | None, str]


def _tasks(text: str, office: str) -> list[Row]:
    frame = (_default if office == "default" else _harbour)(text)
    assert frame.question is None and frame.decline is None, frame
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    ("office", "text", "expected"),
    [
        # the class's analogues: the thing handed on by "it" keeps its recipient
        (
            "default",
            "print my file and take it to wang, oh and a coffee for me",
            [("print", "file", "lee", "wang"), ("produce", "coffee", None, "lee")],
        ),
        (
            "default",
            "print my file and take it to wang, and a coffee for me",
            [("print", "file", "lee", "wang"), ("produce", "coffee", None, "lee")],
        ),
        (
            "default",
            "copy my document and bring it to Zhang, plus a water for me",
            [("copy", "document", "lee", "zhang"), ("produce", "water", None, "lee")],
        ),
        (
            "default",
            "copy my document and bring it to Zhang, also a water for me",
            [("copy", "document", "lee", "zhang"), ("produce", "water", None, "lee")],
        ),
        (
            "default",
            "make a coffee and take it to Sun, and some water to me",
            [("produce", "coffee", None, "sun"), ("produce", "water", None, "lee")],
        ),
        (
            "default",
            "fetch Hu's stapler and take it to Wang, and a coffee for me",
            [("transfer", "stapler", "hu", "wang"), ("produce", "coffee", None, "lee")],
        ),
        (
            "default",
            "grab my book and bring it to Mao, and Hu's stapler for me",
            [("transfer", "book", "lee", "mao"), ("transfer", "stapler", "hu", "lee")],
        ),
        # one clause, two objects: "for me" after the second object is its own, no favour
        (
            "default",
            "bring my stapler to wang and a coffee for me",
            [("transfer", "stapler", "lee", "wang"), ("produce", "coffee", None, "lee")],
        ),
        (
            "default",
            "get me a coffee and print the slides for Sun",
            [("produce", "coffee", None, "lee"), ("print", "file", "lee", "sun")],
        ),
        (
            "default",
            "a water for Mao and bring Wang's stapler to me",
            [("produce", "water", None, "mao"), ("transfer", "stapler", "wang", "lee")],
        ),
        (
            "harbour",
            "print my file and take it to Rose, oh and a tea for me",
            [("print", "file", "may", "rose"), ("produce", "tea", None, "may")],
        ),
        (
            "harbour",
            "scan my document and bring it to Pat, plus a tea for me",
            [("copy", "document", "may", "pat"), ("produce", "tea", None, "may")],
        ),
        (
            "harbour",
            "bring my ruler to Jack and a tea for me",
            [("transfer", "ruler", "may", "jack"), ("produce", "tea", None, "may")],
        ),
        (
            "harbour",
            "get me a tea and print the agenda for Bill",
            [("produce", "tea", None, "may"), ("print", "file", "may", "bill")],
        ),
        (
            "harbour",
            "a tea for Mark and bring Rose's ruler to me",
            [("produce", "tea", None, "mark"), ("transfer", "ruler", "rose", "may")],
        ),
        # the recipient said by a putting verb's "with", or as the owner of the place the
        # thing is left at, closes the part as "to X" does (round 193's class: the printout
        # went to the speaker of the later "for me")
        (
            "default",
            "print my report and drop it with Zhang, then a coffee for me",
            [("print", "file", "lee", "zhang"), ("produce", "coffee", None, "lee")],
        ),
        (
            "default",
            "print my report and drop it with Zhang, and a coffee for me",
            [("print", "file", "lee", "zhang"), ("produce", "coffee", None, "lee")],
        ),
        (
            "default",
            "print my report and drop it at Zhang's desk, then a coffee for me",
            [("print", "file", "lee", "zhang"), ("produce", "coffee", None, "lee")],
        ),
        (
            "harbour",
            "print my agenda and drop it with Rose, then a tea for me",
            [("print", "file", "may", "rose"), ("produce", "tea", None, "may")],
        ),
    ],
)
def test_each_part_keeps_its_own_recipient(office: str, text: str, expected: list[Row]) -> None:
    assert _tasks(text, office) == expected


@pytest.mark.parametrize(
    ("office", "text", "expected"),
    [
        # neighbours: one recipient named after both things is both's
        (
            "default",
            "print the slides and bring them and a coffee to Zhang",
            [("print", "file", "lee", "zhang"), ("produce", "coffee", None, "zhang")],
        ),
        (
            "default",
            "print my file and bring it and a water to Sun",
            [("print", "file", "lee", "sun"), ("produce", "water", None, "sun")],
        ),
        (
            "harbour",
            "print my file and bring it and a tea to Grace",
            [("print", "file", "may", "grace"), ("produce", "tea", None, "grace")],
        ),
        # "for me" ending the clause right after "to X" is still a favour
        ("default", "take my stapler to Zhang for me", [("transfer", "stapler", "lee", "zhang")]),
        ("harbour", "take my ruler to Jack for me", [("transfer", "ruler", "may", "jack")]),
        # a part with its own verb and "me" is read as before
        (
            "default",
            "print my file and take it to wang, also bring me a coffee",
            [("print", "file", "lee", "wang"), ("produce", "coffee", None, "lee")],
        ),
    ],
)
def test_one_recipient_for_things_handed_together(
    office: str, text: str, expected: list[Row]
) -> None:
    assert _tasks(text, office) == expected


@pytest.mark.parametrize(
    ("office", "text", "question"),
    [
        (
            "default",
            "print my file and take it to wang, and a coffee",
            "Shall I print your file for Wang Fang and get coffee for you?",
        ),
        (
            "default",
            "print my file and take it to wang, and some water",
            "Shall I print your file for Wang Fang and get water for you?",
        ),
        (
            "harbour",
            "print my file and take it to Rose, and a tea",
            "Shall I print your file for Rose Adeyemi and get tea for you?",
        ),
    ],
)
def test_a_new_part_with_no_recipient_is_restated_first(
    office: str, text: str, question: str
) -> None:
    """For the requester or for the one the thing before went to? Nothing decides: the
    whole request is restated and asked before anything moves."""
    frame = (_default if office == "default" else _harbour)(text)
    assert frame.tasks == [] and frame.question == question, frame


def test_a_pronoun_before_a_thing_still_receives_it() -> None:
    """ "bring them a coffee" (no "and"): "them" is whom the coffee is for, asked who."""
    frame = _default("print the slides and bring them a coffee")
    assert frame.tasks == [] and frame.question is not None and "them" in frame.question


@pytest.mark.parametrize(
    ("office", "text", "expected"),
    [
        (
            "default",
            "copy my document and get a water, all for Sun",
            [("copy", "document", "lee", "sun"), ("produce", "water", None, "sun")],
        ),
        (
            "harbour",
            "scan my document and make a tea, both for Jack",
            [("copy", "document", "may", "jack"), ("produce", "tea", None, "jack")],
        ),
    ],
)
def test_a_recipient_said_of_both_parts_is_each_parts(
    office: str, text: str, expected: list[Row]
) -> None:
    assert _tasks(text, office) == expected


@pytest.mark.parametrize(
    ("office", "text", "question"),
    [
        # the class's neighbour: restated with the one recipient for both, never the
        # printout to the requester
        (
            "default",
            "print my file and a coffee, both for Wang",
            "Shall I print your file for Wang Fang and get coffee for Wang Fang?",
        ),
        (
            "harbour",
            "print my file and a tea, both for Grace",
            "Shall I print your file for Grace Huang and get tea for Grace Huang?",
        ),
        # must not change: "for Wang" with no "both" is the coffee's alone, as restated
        (
            "default",
            "print my file and a coffee for Wang",
            "Shall I print your file for you and get coffee for Wang Fang?",
        ),
        # a part that named its own recipient keeps it
        (
            "default",
            "print my file for Zhang and a coffee, both for Wang",
            "Shall I print your file for Zhang Wei and get coffee for Wang Fang?",
        ),
    ],
)
def test_both_for_restates_one_recipient(office: str, text: str, question: str) -> None:
    frame = (_default if office == "default" else _harbour)(text)
    assert frame.tasks == [] and frame.question == question, frame
