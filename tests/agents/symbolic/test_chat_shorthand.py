"""Chat shorthand of a function word ("frm", "cn", "cld") is read as the word, so "a radio
frm drew" names whom it comes from (blind round 34: "cn u bring me a curin light frm olive,
ask her 1st obvs" fetched anyone's). Only spellings that are no other English word."""

from __future__ import annotations

import pytest

from helpers.port_office import port_office
from helpers.reading import frame_reader

_frame = frame_reader(port_office, "tom")


@pytest.mark.parametrize(
    "text",
    [
        "cn u bring me a radio frm drew, ask him 1st obvs",
        "cld u get me a radio frm drew",
    ],
)
def test_shorthand_from_names_the_owner(text: str) -> None:
    frame = _frame(text)
    assert [(t.owner, t.recipient) for t in frame.tasks] == [("drew", "tom")], frame


def test_the_word_written_out_reads_the_same() -> None:
    assert (
        _frame("can you bring me a radio from drew").tasks
        == _frame("cn u bring me a radio frm drew").tasks
    )
