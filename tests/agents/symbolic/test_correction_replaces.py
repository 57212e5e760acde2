"""A correction inside the message replaces what it corrects; it never cancels the request and
never keeps both readings: "get me a coffee - sorry, make that a water, I've had 3 already"
dropped the request (the "had already" read as a withdrawal), and "get a stapler to Zhang -
sorry, I mean one FROM Zhang" took another colleague's stapler to Zhang (only the name was
replaced, not the way the thing goes)."""

from __future__ import annotations

import pytest

from assistantx.core.office import load_office
from helpers.reading import frame_reader

_frame = frame_reader(load_office, "lee")


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("get me a coffee - sorry, make that a water, I've had 3 already", "water"),
        ("get me a coffee - sorry, make it a water", "water"),
        ("a coffee please, sorry, make that a water, had two already", "water"),
        ("bring me a coffee, actually make it a water", "water"),
    ],
)
def test_the_corrected_thing_is_made(text: str, item: str) -> None:
    frame = _frame(text)
    assert frame.decline is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("produce", item, "lee")], frame


@pytest.mark.parametrize(
    ("text", "owner", "recipient"),
    [
        ("i need to get a stapler to Zhang - sorry, I mean I need one FROM Zhang", "zhang", "lee"),
        ("i need to get a stapler to Zhang - sorry, I mean from Zhang", "zhang", "lee"),
        # the receiver named with no "to" ("bring Zhang a stapler"): from them, to the speaker
        ("bring Zhang a stapler - sorry, I mean one from Zhang", "zhang", "lee"),
        ("get Zhang a stapler, sorry, I meant one from Zhang", "zhang", "lee"),
        ("grab Wang a stapler - no wait, I mean one from Wang", "wang", "lee"),
        ("get a stapler from Zhang, sorry, I mean to Zhang", None, "zhang"),
        ("take my book to Wang - sorry, I mean to Zhang", "lee", "zhang"),
        ("take my document to Wang, no wait, not to Wang, to Zhang", "lee", "zhang"),
        ("send my document to Chen, sorry, Liu Yang I mean", "lee", "liu"),
        ("take my document to Yang? Sorry - I mean Liu Yang, not Yang Lei.", "lee", "liu"),
        ("give my book to Yang. Sorry - I meant Yang Lei, not Liu Yang", "lee", "yang"),
        ("bring me Zhang's stapler - sorry, I meant Wang's", "wang", "lee"),
    ],
)
def test_the_correction_replaces_who_and_which_way(
    text: str, owner: str | None, recipient: str
) -> None:
    frame = _frame(text)
    assert [(t.kind, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", owner, recipient)
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        "get me a coffee, I've had 3 already",  # no correction: had already, as before
        "get me a coffee. never mind, I've had one already",
    ],
)
def test_had_already_without_a_correction_still_withdraws(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.decline is not None, frame
