"""A word for an outsider that modifies the thing after it is no recipient (round 61's class):
"send my volunteer rota spreadsheet to ..." asked who "my volunteer" was. The existing rule
took the outsider noun as a modifier only with the item right after it ("my guest rundown");
a word the dictionary does not know ("rota") between them ended the phrase. Now the words
after it that go on as one noun phrase to the office's item (nouns, unknown words) make it
the item's modifier; an outsider receiver ("give my client a copy") is asked about as before."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office
from helpers.reading import frame_reader

_DEFAULT = frame_reader(default_office, "lee")


@pytest.mark.parametrize(
    ("text", "recipient"),
    [
        ("send my volunteer rota spreadsheet to Wang", "wang"),
        ("send my customer rota spreadsheet to Wang", "wang"),
        ("give the visitor rota spreadsheet to Wang", "wang"),
        ("send my volunteer rota spreadsheet to Wang x", "wang"),
        ("send my client list spreadsheet to Wang", "wang"),
        ("forward my customer contacts file to Mao", "mao"),
    ],
)
def test_the_outsider_word_modifies_the_thing(text: str, recipient: str) -> None:
    frame = _DEFAULT(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("send_file", "file", recipient)
    ], frame


@pytest.mark.parametrize(
    ("text", "who"),
    [
        ("give my client a copy", "my client"),
        ("give my volunteer the spreadsheet", "my volunteer"),
        ("give the visitor Wang's file", "the visitor"),
        ("a coffee for the visitor", "the visitor"),
        ("send my volunteer rota spreadsheet to the volunteer", "the volunteer"),
    ],
)
def test_an_outsider_receiver_is_still_asked_about(text: str, who: str) -> None:
    frame = _DEFAULT(text)
    assert frame.tasks == [] and frame.question is not None, frame
    assert f"I don't know who {who} is" in frame.question, frame
