"""A grumble with no request ("ugh still miles to go with these invoices", "gonna be a long day",
"won't be done till 6", "ugh" alone) is venting: answered in words, nothing moves, and a
colleague whose name is a word of it (Miles of "miles to go") is no party
(``reading.grumble``). A request beside a grumble, and "a coffee to go", are still asked."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office
from helpers.glazing_lab import glazing_lab
from helpers.reading import frame_reader

_lab = frame_reader(glazing_lab, "ada")
_default = frame_reader(default_office, "hu")


@pytest.mark.parametrize(
    "text",
    [
        "ugh still miles to go with these invoices, not finishing today",
        "still miles to go",
        "ugh frank, gonna be a long day",
        "sigh. won't be done till 6",
        "ugh",
    ],
)
def test_a_grumble_asks_nothing(text: str) -> None:
    frame = _lab(text)
    assert frame.question is None and not frame.tasks, frame


def test_a_grumble_about_things_the_office_has_asks_nothing() -> None:
    frame = _default("ugh still miles to go with these invoices, not finishing today")
    assert frame.question is None and not frame.tasks, frame


@pytest.mark.parametrize(
    ("text", "item", "recipient"),
    [
        ("ugh, bring me a pen", "pen", "ada"),  # must not change
        ("bring miles a pen", "pen", "miles"),  # must not change
        ("can i get a pen to go", "pen", "ada"),  # must not change
    ],
)
def test_requests_beside_or_like_a_grumble_are_asked(text: str, item: str, recipient: str) -> None:
    assert [(t.item, t.recipient) for t in _lab(text).tasks] == [(item, recipient)]


def test_a_request_beside_a_grumble_is_asked() -> None:
    frame = _default("print my document, gonna be a long day")
    assert [(t.kind, t.owner) for t in frame.tasks] == [("print", "hu")], frame
