"""A message cut off after a preposition or an article (blind rounds 20 to 22's class, on a
conservation department no sentence was written for, ``helpers.conservation_lab``): "can you
take my sample tray to" says where the tray goes only up to "to"; on main the tray was
delivered back to the requester. Asked where it should go (or who should get it), never
delivered; the answer completes the sentence. A preposition stranded by a clause of its own
("the tray I asked for") is no cut."""

from __future__ import annotations

import pytest

from helpers.conservation_lab import conservation_lab
from helpers.reading import answered_reader, frame_reader

_frame = frame_reader(conservation_lab, "nell")
_answered = answered_reader(conservation_lab, "nell")


@pytest.mark.parametrize(
    "text",
    [
        "can you take my sample tray to",
        "can you take my tray to the",
        "please take Joss's battery to",
        "could you take the clay over to",
        "can you take my sample tray from the cold store to",
        "take my checklist to the",
        "can you bring my phone to",
    ],
)
def test_a_message_cut_off_is_asked_about(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.decline is None, frame
    assert frame.question is not None and "cut off" in frame.question, frame


def test_the_answer_completes_the_sentence() -> None:
    frame = _answered("can you take my sample tray to", ["Joss"])
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("sample_tray", "nell", "joss")
    ], frame
    frame = _answered("can you take my sample tray to", ["to Joss"])
    assert [(t.item, t.recipient) for t in frame.tasks] == [("sample_tray", "joss")], frame


@pytest.mark.parametrize(
    ("text", "item", "recipient"),
    [
        ("can you take my sample tray to Joss", "sample_tray", "joss"),
        ("bring me the battery Joss was talking about", "battery", "nell"),
        ("bring me some clay", "clay", "nell"),
    ],
)
def test_a_whole_sentence_is_read_as_before(text: str, item: str, recipient: str) -> None:
    frame = _frame(text)
    assert [(t.item, t.recipient) for t in frame.tasks] == [(item, recipient)] or (
        frame.question is not None and "cut off" not in frame.question
    ), frame
