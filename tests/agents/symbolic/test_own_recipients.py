"""Each thing's own "for X" in a list of two (fix154b, class 5): in "A for X and B of my C for
Y", read as two parts (a product named with what it is made of, beside another thing), X
receives A and Y receives B; where only one part says whom, the clause reads as before
(``reading.own_recipients``)."""

from __future__ import annotations

import pytest
from _offices import tasks_of


@pytest.mark.parametrize(
    ("office", "requester", "text", "expected"),
    [
        # the class's own analogue: the latte was carried to Fang
        (
            "default",
            "zhou",
            "a latte for me and a copy of my contract for Fang",
            [("produce", "coffee", None, "zhou"), ("copy", "document", "zhou", "wang")],
        ),
        (
            "default",
            "zhou",
            "a coffee for me and a printout of my file for Zhang",
            [("produce", "coffee", None, "zhou"), ("print", "file", "zhou", "zhang")],
        ),
        # variants: the other order, other people, a question's words, another office
        (
            "default",
            "zhou",
            "a copy of my contract for Fang and a latte for me",
            [("copy", "document", "zhou", "wang"), ("produce", "coffee", None, "zhou")],
        ),
        (
            "default",
            "zhou",
            "could I get a printout of my file for Wang and a coffee for Zhang",
            [("print", "file", "zhou", "wang"), ("produce", "coffee", None, "zhang")],
        ),
        (
            "harbour",
            "may",
            "a tea for me and a printout of my file for Will",
            [("produce", "tea", None, "may"), ("print", "file", "may", "will")],
        ),
        (
            "harbour",
            "may",
            "a tea for Will and a scan of my contract for me",
            [("produce", "tea", None, "will"), ("copy", "document", "may", "may")],
        ),
    ],
)
def test_each_thing_goes_to_its_own_for(
    office: str, requester: str, text: str, expected: list[tuple[str, str, str | None, str]]
) -> None:
    assert tasks_of(office, text, requester) == expected


# -- must not change: one "for" for the whole list, or one said before it -------------------
@pytest.mark.parametrize(
    ("text", "expected"),
    [
        (
            "a coffee and a copy of my contract for Fang",
            [("produce", "coffee", None, "wang"), ("copy", "document", "zhou", "wang")],
        ),
        (
            "bring me a coffee and a printout of my file",
            [("produce", "coffee", None, "zhou"), ("print", "file", "zhou", "zhou")],
        ),
        (
            "bring a coffee for me and a stapler for Wang",
            [("produce", "coffee", None, "zhou"), ("transfer", "stapler", None, "wang")],
        ),
    ],
)
def test_one_recipient_for_the_list_stands(
    text: str, expected: list[tuple[str, str, str | None, str]]
) -> None:
    assert tasks_of("default", text, "zhou") == expected


@pytest.mark.parametrize(
    ("office", "requester", "text", "expected"),
    [
        # "a tea for Wang and a stapler for me" where the office has no stapler (harbour) or
        # no such thing at all: the tea keeps its own "for", never carried to the speaker
        (
            "harbour",
            "may",
            "a tea for Will and a stapler for me",
            [("produce", "tea", None, "will")],
        ),
        (
            "harbour",
            "may",
            "a tea for Will and a widget for Rose",
            [("produce", "tea", None, "will")],
        ),
        (
            "default",
            "zhou",
            "a coffee for Wang and a muffin for me",
            [("produce", "coffee", None, "wang")],
        ),
    ],
)
def test_the_one_thing_read_keeps_its_own_for(
    office: str, requester: str, text: str, expected: list[tuple[str, str, str | None, str]]
) -> None:
    assert tasks_of(office, text, requester) == expected


def test_two_things_read_each_keep_their_own_for() -> None:
    assert tasks_of("harbour", "a tea for Will and a ruler for me", "may") == [
        ("produce", "tea", None, "will"),
        ("transfer", "ruler", None, "may"),
    ]
