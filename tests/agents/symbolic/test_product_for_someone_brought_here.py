"""A request for the office's product "for" someone outside the office that says itself where
it goes ("we need a new label for the man in bed 4, can u print one and bring it here"): the
outsider is whom it is about, the requester receives it, and "one" after the service's verb is
the product named before it (blind round 40's class: it asked "Shall I bring it to you
instead?" and read the reply as a no; the round's own sentences were never read). Without
"here" or "me" the outsider is still asked about; a plain "bring me one" is read as before."""

from __future__ import annotations

import pytest

from helpers.reading import frame_reader
from helpers.ward import ward

_frame = frame_reader(ward, "omar")


@pytest.mark.parametrize(
    "text",
    [
        "we need a new label for the man in bed 4, can u print one and bring it here",
        "we need a label for the patient in bed 2, could you print one and drop it over to me",
        "need labels for the lady in bay 3, can you print some and bring them to me pls",
        "print a label for the man in bed 4 and bring it here",
        "i need a label, could you print me one",
    ],
)
def test_the_product_is_made_and_brought_to_the_requester(text: str) -> None:
    frame = _frame(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("produce", "label", "omar")], (
        frame
    )


@pytest.mark.parametrize(
    "text",
    [
        "print a label for the man at the desk",
        "we need a label for the man in bed 4, can you print one and take it to him",
    ],
)
def test_an_outsider_as_the_recipient_is_still_asked_about(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is not None, frame
    assert "Shall I bring it to you instead" in frame.question


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("i need a ruler, can you bring me one", [("transfer", "ruler", "omar")]),
        ("print a label for the visitor and give it to Zoe", [("produce", "label", "zoe")]),
        ("print my draft", [("print", "file", "omar")]),
    ],
)
def test_other_requests_keep_their_reading(text: str, expected: list[tuple[str, str, str]]) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == expected, frame
