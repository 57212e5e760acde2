"""Whether a one-word name that is also a word means the person (``core.name_reading``), on the
slots that decide it: the reader and the consent guard both read names with this function."""

from __future__ import annotations

import pytest

from assistantx.core.name_reading import NameSlot, read_name


@pytest.mark.parametrize(
    ("slot", "reading"),
    [
        # the subject of a modal's question, before its verb (round 21: "Can Penny sign my
        # damage report" asked "Penny, or penny sign?")
        (NameSlot(word="penny", written="Penny", prev="can", next="sign"), "person"),
        (NameSlot(word="holly", written="holly", prev="could", next="bring"), "person"),
        # "who" is said of people only (round 18: "it's fern who needs the hard copy")
        (NameSlot(word="fern", written="fern", prev="it", next="who"), "person"),
        # a negated auxiliary's subject, as "grace has" is (fix175c: "grace hasnt approved
        # my leave form yet. can you get her to sign it" asked who "her" was)
        (NameSlot(word="grace", written="grace", opens=True, next="hasnt"), "person"),
        (NameSlot(word="mark", written="mark", opens=True, next="didnt"), "person"),
        # the subject of a clause after a verb that takes one (fix201a: "i hope mark wont
        # mind but can i borrow his ruler" asked who "his" was)
        (NameSlot(word="mark", written="mark", prev="hope", next="wont"), "person"),
        (NameSlot(word="mark", written="mark", prev="know", next="is"), "person"),
        (NameSlot(word="mark", written="mark", prev="hope", next="the"), "word"),
        # the ordinary word stays the word
        (NameSlot(word="may", written="may", opens=True, next="i"), "word"),
        (NameSlot(word="grace", written="grace", prev="the", next="period"), "word"),
        (NameSlot(word="will", written="Will", opens=True, next="you"), "word"),
        (NameSlot(word="penny", written="penny", prev="a", next="jar"), "word"),
        (NameSlot(word="may", written="may", prev="in"), "word"),
    ],
)
def test_syntax_decides_a_word_name(slot: NameSlot, reading: str) -> None:
    assert read_name(slot) == reading
