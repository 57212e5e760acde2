"""Blind rounds 43-48, class J2: where two services of one shape work on the same paper (a
photocopy makes a "photocopy", also called a "copy"; certifying makes a "certified copy"),
the product a statement names beside a request that only points back at it ("got a client who
wants a certified copy of her order, can you get one done?") says which service is meant: the
longest product name the lexicon reads ("certified copy", never its "copy") picks the one
that makes it (``OperationChooser.choose``'s ``whole``). A request naming its own product is
read as before ("a copy of my order" is a photocopy). On ``helpers.county_court``; the
rounds' own offices and sentences were never read."""

from __future__ import annotations

import pytest

from helpers.county_court import county_court
from helpers.reading import frame_reader

_frame = frame_reader(county_court, "tess")


@pytest.mark.parametrize(
    ("text", "operation"),
    [
        (
            "got a litigant at the counter who wants a certified copy of her order, I've got "
            "the original here, can you get one done?",
            "certify",
        ),
        ("got a client who wants a certified copy of her order, can you get one done?", "certify"),
        ("a visitor needs a certified copy of the order, can you get one done?", "certify"),
        ("can I get a certified copy of my order", "certify"),
        ("could you make me a certified copy of my judgment", "certify"),
        ("can I get a copy of my order", "photocopy"),
        ("please make a copy of my order", "photocopy"),
    ],
)
def test_the_product_named_picks_the_service(text: str, operation: str) -> None:
    frame = _frame(text)
    assert [(t.item, t.operation, t.recipient) for t in frame.tasks] == [
        ("court_order", operation, "tess")
    ], frame.question
