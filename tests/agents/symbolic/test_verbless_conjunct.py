"""A second conjunct without a verb takes the request's verb (``reading.verbless_conjunct``):
"get Wang to sign my contract, and a coffee for me while you're at it" asked what to do with
the coffee (the "get" is Wang's, for the signing); "take my stapler to Wang and Sun a coffee"
asked whether the stapler went to Wang or to Sun. A second signer, a second paper for the
signing and a second object of one verb are read as before."""

from __future__ import annotations

from typing import Any

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "lin")
_harbour = frame_reader(harbour_office, "may")

Row = tuple[str, str, str | None, str | None, str | None]


def _rows(frame: Any) -> list[Row]:
    return [(t.kind, t.item, t.owner, t.recipient, t.actor) for t in frame.tasks]


_SIGNED = ("sign", "document", "lin", "lin", "wang")


@pytest.mark.parametrize(
    ("text", "also"),
    [
        (
            "Get Wang to sign my contract, and a coffee for me while you're at it",
            ("produce", "coffee", None, "lin", None),
        ),
        (
            "Get Wang to sign my contract, and some water for me while you're at it",
            ("produce", "water", None, "lin", None),
        ),
        (
            "Get Wang to sign my contract, and a coffee for Sun",
            ("produce", "coffee", None, "sun", None),
        ),
        (
            "get Wang to sign my contract and a stapler for me",
            ("transfer", "stapler", None, "lin", None),
        ),
    ],
)
def test_default_office_thing_after_get_someone_to_work_is_got(text: str, also: Row) -> None:
    frame = _default(text)
    assert frame.question is None, frame
    assert _rows(frame) == [_SIGNED, also], frame


@pytest.mark.parametrize(
    ("text", "first", "second"),
    [
        (
            "take my stapler to Wang and Sun a coffee",
            ("transfer", "stapler", "lin", "wang", None),
            ("produce", "coffee", None, "sun", None),
        ),
        (
            "take my book to Zhang and Wang a water",
            ("transfer", "book", "lin", "zhang", None),
            ("produce", "water", None, "wang", None),
        ),
        # the second person said with "for", before the thing: the coffee had gone to Lin
        (
            "bring a coffee to Zhang and for me a water",
            ("produce", "coffee", None, "zhang", None),
            ("produce", "water", None, "lin", None),
        ),
        (
            "take my book to Zhang and for Wang a stapler",
            ("transfer", "book", "lin", "zhang", None),
            ("transfer", "stapler", None, "wang", None),
        ),
    ],
)
def test_default_office_gapped_giving_verb(text: str, first: Row, second: Row) -> None:
    frame = _default(text)
    assert frame.question is None, frame
    assert _rows(frame) == [first, second], frame


@pytest.mark.parametrize(
    ("text", "rows"),
    [
        (
            "get Mark to sign my contract, and a tea for me while you're at it",
            [("sign", "document", "may", "may", "mark"), ("produce", "tea", None, "may", None)],
        ),
        (
            "Get Grace to sign my form and a ruler for me",
            [("sign", "document", "may", "may", "grace"), ("transfer", "ruler", None, "may", None)],
        ),
        (
            "take my tape dispenser to Mark and Rose a tea",
            [("transfer", "tape", "may", "mark", None), ("produce", "tea", None, "rose", None)],
        ),
    ],
)
def test_harbour_verbless_conjuncts(text: str, rows: list[Row]) -> None:
    frame = _harbour(text)
    assert frame.question is None, frame
    assert _rows(frame) == rows, frame


def test_a_second_paper_stays_the_works() -> None:
    # "the invoice" is a paper the signing may take too: no "get" put before it
    frame = _default("get Wang to sign my contract and the invoice")
    assert all(t.kind == "sign" for t in frame.tasks), frame


def test_a_second_name_without_a_thing_moves_nothing_new() -> None:
    frame = _default("get Wang to sign my contract and Zhang")
    assert all(t.kind == "sign" for t in frame.tasks), frame


@pytest.mark.parametrize(
    ("text", "rows"),
    [
        (
            "bring Wang my stapler and my scissors",
            [
                ("transfer", "stapler", "lin", "wang", None),
                ("transfer", "scissors", "lin", "wang", None),
            ],
        ),
        (
            "bring Wang and Sun a coffee",
            [("produce", "coffee", None, "wang", None), ("produce", "coffee", None, "sun", None)],
        ),
    ],
)
def test_one_verbs_own_objects_and_recipients_are_unchanged(text: str, rows: list[Row]) -> None:
    assert _rows(_default(text)) == rows


def test_harbour_one_verbs_two_objects_are_unchanged() -> None:
    assert _rows(_harbour("bring Mark my ruler and my tape dispenser")) == [
        ("transfer", "ruler", "may", "mark", None),
        ("transfer", "tape", "may", "mark", None),
    ]


def test_two_recipients_of_one_thing_still_ask() -> None:
    frame = _default("take my stapler to Wang and Sun")
    assert frame.tasks == [] and frame.question is not None, frame
