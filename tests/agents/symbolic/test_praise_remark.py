"""Praise of someone's work with no request ("noble effort on the stocktake yesterday,
everyone", "great job today, team", "well done all") is a remark, answered in words, not met
with "what should I do?" (blind rounds 43-48's class: a colleague's name that is also an
ordinary word praised the work as an adjective). Requests that name those colleagues, and a
request after the praise, are read as before."""

from __future__ import annotations

import pytest

from helpers.reading import frame_reader
from helpers.word_names import word_names

_frame = frame_reader(word_names, "petra")


@pytest.mark.parametrize(
    "text",
    [
        "noble effort on the stocktake yesterday, everyone",
        "Noble effort on the stocktake yesterday, everyone",
        "great job today, team",
        "brilliant work on the inventory!",
        "really solid effort this week everyone",
        "well done all",
        "Well done on the tidy-up, team!",
        "nice one on the stocktake, folks",
        # remarks where a name word is the ordinary word
        "to be frank, the new rota is a mess",
        "the phone bill came in high again, ugh",
        "we got the grant!!",
        # praise of a thing just told of (round 254: "..., lovely thing" was asked about)
        "the new mug has a lid, lovely thing",
        "lovely thing",
        "the new kettle boils in a minute. great kit",
    ],
)
def test_a_remark_is_answered_in_words(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and frame.decline_outcome == "done", frame


@pytest.mark.parametrize(
    ("text", "kind", "recipient"),
    [
        ("great job, can you bring me a mug", "transfer", "petra"),
        ("well done all, could you bring Grant a mug", "transfer", "grant"),
        ("bring Bill my stapler", "transfer", "bill"),
        ("ask Frank to sign my form", "sign", "petra"),
        ("could you bring Noble a mug", "transfer", "noble"),
        ("lovely thing, can you bring me a mug", "transfer", "petra"),
        ("one more thing - could you bring me a mug", "transfer", "petra"),
        ("last thing, could you bring me a mug", "transfer", "petra"),
    ],
)
def test_a_request_beside_or_naming_them_is_read_as_before(
    text: str, kind: str, recipient: str
) -> None:
    frame = _frame(text)
    assert [(t.kind, t.recipient) for t in frame.tasks] == [(kind, recipient)], frame


def test_praise_asking_for_work_is_no_remark() -> None:
    frame = _frame("great job, could you get Frank to sign my form")
    assert [(t.kind, t.actor) for t in frame.tasks] == [("sign", "frank")], frame
