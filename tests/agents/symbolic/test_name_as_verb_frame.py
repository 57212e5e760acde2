"""A colleague's given name that is also a verb, after "to" (or a modal) and followed by
what a verb takes, is the verb: "I'm out of highlighters to mark up 20 pages" wants a
highlighter for the speaker, never one delivered to Mark (fix103h, class 1's analogue;
``core.name_reading._verb_frame``). A particle, an object's determiner, a number or an
object pronoun after the name makes the verb; the end of the clause, a pause, a possessive,
"please", a place or "to" + verb after it keeps the person. With a capital and the verb's
syntax, both readings fit: the reader asks."""

from __future__ import annotations

import pytest
from _offices import tasks_of

from assistantx.core.name_reading import NameSlot, read_name
from helpers.reading import frame_reader
from helpers.verb_names import verb_names

_small = frame_reader(verb_names, "ines")


@pytest.mark.parametrize(
    "text",
    [
        "I'm out of highlighters to mark up 20 pages",
        "I need a highlighter to mark the boxes",
        "I need the ruler to mark out the lines",
        "can I borrow a ruler? I have to mark them up",
        "could I get a highlighter so I can mark up the drafts",
    ],
)
def test_harbour_a_name_before_what_a_verb_takes_is_the_verb(text: str) -> None:
    tasks = tasks_of("harbour", text, "rose")
    assert [(kind, recipient) for kind, _, _, recipient in tasks] == [("transfer", "rose")]


@pytest.mark.parametrize(
    "text",
    [
        "I need a tape measure to chase up the surveys",
        "can I borrow a tape measure to mark out the plot",
    ],
)
def test_a_small_office_reads_the_verb(text: str) -> None:
    frame = _small(text)
    assert [(t.kind, t.recipient) for t in frame.tasks] == [("transfer", "ines")], frame


# -- must not change: the person the thing goes to ----------------------------------------
@pytest.mark.parametrize(
    ("text", "recipient"),
    [
        ("take my document to Mark", "mark"),
        ("take my document to mark please", "mark"),
        ("take my document to Mark this afternoon", "mark"),
        ("take my document to Mark over in the copy room", "mark"),
    ],
)
def test_harbour_a_recipient_stays_the_person(text: str, recipient: str) -> None:
    assert tasks_of("harbour", text, "rose") == [("transfer", "document", "rose", recipient)]


def test_given_to_sign_is_the_person_and_the_signing() -> None:
    tasks = tasks_of("harbour", "give my document to Mark to sign", "rose")
    assert [(kind, owner) for kind, _, owner, _ in tasks] == [("sign", "rose")]
    frame = _small("take my report to Chase to sign")
    assert [(t.kind, t.item) for t in frame.tasks] == [("sign", "report")], frame


def test_a_small_office_recipient_stays_the_person() -> None:
    frame = _small("take the tape measure to Chase")
    assert [(t.kind, t.recipient) for t in frame.tasks] == [("transfer", "chase")], frame


@pytest.mark.parametrize(
    ("slot", "reading"),
    [
        (NameSlot(word="mark", written="mark", prev="to", next="up", after_next="20"), "word"),
        (
            NameSlot(word="chase", written="chase", prev="to", next="the", after_next="invoices"),
            "word",
        ),
        (NameSlot(word="mark", written="mark", prev="to", next="20", after_next="pages"), "word"),
        (NameSlot(word="mark", written="mark", prev="can", next="him", after_next="down"), "word"),
        # a capital and the verb's syntax: either may be meant
        (NameSlot(word="mark", written="Mark", prev="to", next="up", after_next="20"), "ask"),
        # a time, a place or the clause's end after the name: the recipient
        (
            NameSlot(word="drew", written="Drew", prev="to", next="this", after_next="afternoon"),
            "person",
        ),
        (NameSlot(word="mark", written="mark", prev="to", next="over", after_next="in"), "person"),
        (
            NameSlot(word="chase", written="Chase", prev="to", next="to", after_next="sign"),
            "person",
        ),
        (NameSlot(word="mark", written="mark", prev="to", next="please"), "person"),
        (NameSlot(word="mark", written="mark", prev="to", next="", after_next=""), "person"),
    ],
)
def test_the_verb_frame_decides(slot: NameSlot, reading: str) -> None:
    assert read_name(slot) == reading
