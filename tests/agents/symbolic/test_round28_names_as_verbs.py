"""A colleague's given name that is also a verb, used as the verb beside the request (blind
round 28's class, on an office no sentence was written for, ``helpers.rota_desk``: colleagues
called Mark, Bill and Chase). "I'd rather not have to mark it down later" is the verb, so the
printout goes to whom the request names, never to Mark; the reader and the consent guard
decide with the same function (``core.name_reading.read_name``)."""

from __future__ import annotations

import pytest

from assistantx.core.name_reading import NameSlot, read_name
from assistantx.runtime.recipients import named_recipients
from helpers.consent_memory import memory
from helpers.reading import frame_reader
from helpers.rota_desk import rota_desk

_frame = frame_reader(rota_desk, "ada")


@pytest.mark.parametrize(
    "text",
    [
        "print my rota and give it to Otto? I'd rather not have to mark it down later",
        "print my rota and give it to Otto, I need to mark it up before the meeting",
        "could you print my rota and take it to Otto? we need to chase them later",
        "could you print my rota and take it to Otto? we should chase them later",
        "print my rota and hand it to Otto, I'd rather not bill them twice",
    ],
)
def test_a_name_in_a_verb_slot_before_it_is_the_verb(text: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("print", "rota", "otto")]
    assert named_recipients(rota_desk(), memory("ada", text)) == {"otto"}


@pytest.mark.parametrize(
    ("text", "recipient"),
    [
        ("print my rota and give it to Mark", "mark"),
        ("print my rota and give it to mark, it's for the meeting", "mark"),
        ("print my rota and give it to Mark, it is urgent", "mark"),
        ("print my rota and take it to Chase", "chase"),
    ],
)
def test_a_name_given_to_is_still_the_colleague(text: str, recipient: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("print", "rota", recipient)]
    assert named_recipients(rota_desk(), memory("ada", text)) == {recipient}


def test_a_verb_of_giving_before_the_name_keeps_the_person() -> None:
    frame = _frame("could you bring Bill Otto's ruler")
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("ruler", "otto", "bill")]


@pytest.mark.parametrize(
    ("slot", "reading"),
    [
        (NameSlot(word="mark", written="mark", prev="to", next="it"), "word"),
        (NameSlot(word="chase", written="Chase", prev="should", next="them"), "word"),
        (NameSlot(word="bill", written="bill", prev="not", next="them"), "word"),
        # a pause, or "it's", after the name: the person it was given to
        (
            NameSlot(word="mark", written="Mark", prev="to", next="it", next_after_pause=True),
            "person",
        ),
        (
            NameSlot(word="mark", written="Mark", prev="to", next="it", next_possessive=True),
            "person",
        ),
        # "give Mark it": a verb of giving takes the person before "it"
        (NameSlot(word="mark", written="Mark", prev="give", next="it"), "person"),
    ],
)
def test_the_verb_slot_decides(slot: NameSlot, reading: str) -> None:
    assert read_name(slot) == reading
