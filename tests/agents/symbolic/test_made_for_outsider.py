"""A thing the office makes, asked "for" a capitalised name nobody of the office has, with
"please" and no colleague named ("chopped quail for Blaze please, 160g"), is made for the
speaker, never "who is Blaze?" (reading/made_for_outsider.py). A name close to a colleague's,
a thing not made here, no "please", or a colleague named too are read as before."""

from __future__ import annotations

from typing import Any

import pytest
from _mews_office import mews_office

from assistantx.core.office import load_office
from helpers.reading import frame_reader

_ava = frame_reader(mews_office, "ava")
_lee = frame_reader(load_office, "lee")


@pytest.mark.parametrize(
    ("read", "text", "item", "speaker"),
    [
        (_ava, "chopped quail for Blaze please, 160g", "ration", "ava"),
        (_ava, "day old chicks for Blaze please", "ration", "ava"),
        (_ava, "a ration for Blaze please", "ration", "ava"),
        (_lee, "a coffee for Blaze please", "coffee", "lee"),
    ],
)
def test_made_thing_for_an_outsider_goes_to_the_speaker(
    read: Any, text: str, item: str, speaker: str
) -> None:
    frame = read(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("produce", item, speaker)], (
        frame
    )


@pytest.mark.parametrize(
    ("read", "text", "name"),
    [
        (_ava, "chopped quail for Svm please", "Svm"),  # Sam misspelt
        (_ava, "chopped quail for Blaze", "Blaze"),  # no "please"
        (_lee, "the stapler for Blaze please", "Blaze"),  # nothing made here
    ],
)
def test_a_name_that_may_be_a_colleague_is_still_asked(read: Any, text: str, name: str) -> None:
    frame = read(text)
    assert not frame.tasks and frame.question is not None and name in frame.question, frame


@pytest.mark.parametrize(
    ("read", "text", "recipient"),
    [
        (_ava, "chopped quail for Sam please", "sam"),
        (_ava, "chopped quail for Blaze please, give it to Sam", "sam"),
        (_lee, "a coffee to Wang please", "wang"),
    ],
)
def test_a_colleague_named_still_gets_it(read: Any, text: str, recipient: str) -> None:
    frame = read(text)
    assert [t.recipient for t in frame.tasks] == [recipient], frame


def test_a_misspelt_colleague_is_still_asked() -> None:
    frame = _lee("bring a coffee to Zhnag")
    assert not frame.tasks and frame.question is not None and "Zhnag" in frame.question, frame
