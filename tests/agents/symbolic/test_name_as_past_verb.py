"""A colleague's name that is also a verb's past form ("Drew", "Chased", "Billed"), opening a
sentence with a bare object ("Drew blood from the mare earlier"), is the speaker's own report
with its "I" dropped (blind round 55's class; its office and sentences were never read): told
in words, nothing moved. So is a thing's state said after it with "'s" or "is" and its
participle ("sample's labelled and in the rack"). The name said as a name keeps its reading."""

from __future__ import annotations

import pytest

from helpers.reading import frame_reader
from helpers.vet_yard import vet_yard

_frame = frame_reader(vet_yard, "gwen")


@pytest.mark.parametrize(
    "text",
    [
        "Drew blood from the mare earlier, sample's labelled and in the rack.",
        "Drew blood from the mare earlier.",
        "Drew blood from the colt this morning, it's in the rack",
        "Chased the supplier yesterday, the parts are on the bench.",
        "Billed the client this morning, invoice is in the tray.",
        "Billed time to the client, all done",
        "Drew took blood from the mare, sample's labelled",
        "sample is labelled and in the rack.",
        "mask is tested and on the bench",
    ],
)
def test_a_report_is_told_in_words(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None


@pytest.mark.parametrize(
    ("text", "recipient"),
    [
        ("bring Drew the rack", "drew"),
        ("Drew, bring me the rack", "gwen"),
        ("Bill, bring me the rack", "gwen"),
    ],
)
def test_the_name_said_as_a_name_keeps_its_reading(text: str, recipient: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("transfer", "rack", recipient)
    ], frame


@pytest.mark.parametrize("text", ["Drew needs the rack", "Drew wants a mask"])
def test_a_name_and_its_verb_is_a_need_of_theirs(text: str) -> None:
    frame = _frame(text)
    assert frame.question is not None and "Drew Hale" in frame.question, frame


@pytest.mark.parametrize(
    ("text", "kind"), [("Printed file for Ana", "print"), ("Tested mask for Ana", "heat")]
)
def test_a_participle_before_a_thing_of_the_office_still_asks(text: str, kind: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.recipient) for t in frame.tasks] == [(kind, "ana")], frame
