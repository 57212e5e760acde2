"""News told ("Blaze flew brilliantly today, 2 mins to the lure and straight back to the fist",
"the demo went great today, 5 mins on the stapler and ...") asks nothing: a subject and its past
verb, with verbless fragments after it whose things follow a preposition, is words ("Noted"),
nothing fetched and nothing asked; a capitalised subject nobody of the office is called is no
name to ask about. A request beside the news, a fragment that names its thing first and a
plain verbless request are read as before (screen/narrative.py)."""

from __future__ import annotations

from typing import Any

import pytest
from _mews_office import mews_office

from assistantx.core.office import load_office
from helpers.reading import frame_reader

_ava = frame_reader(mews_office, "ava")
_lee = frame_reader(load_office, "lee")


@pytest.mark.parametrize(
    ("read", "text"),
    [
        (_ava, "Blaze flew brilliantly today, 2 mins to the lure and straight back to the fist"),
        (_ava, "Blaze flew brilliantly today"),
        (_lee, "the demo went great today, 5 mins on the stapler and straight back to the book"),
        (
            _lee,
            "the demo went great today, 5 mins to the scissors and straight back to the stapler",
        ),
        (_lee, "Blaze flew brilliantly today, 2 mins to the stapler and straight back to the book"),
    ],
)
def test_news_with_fragments_asks_nothing(read: Any, text: str) -> None:
    frame = read(text)
    assert not frame.tasks and frame.question is None, frame
    assert frame.decline is not None and frame.decline.startswith("Noted"), frame


@pytest.mark.parametrize(
    ("text", "kind", "item", "recipient"),
    [
        ("a coffee to Wang please", "produce", "coffee", "wang"),
        ("Wang flew in today, bring her a coffee", "produce", "coffee", "wang"),
        ("Wang flew in today, a coffee for her", "produce", "coffee", "wang"),
        ("stapler to Zhang", "transfer", "stapler", "zhang"),
        ("the demo went great today, can you bring me the stapler", "transfer", "stapler", "lee"),
        ("2 coffees to room 3", "produce", "coffee", "lee"),
    ],
)
def test_requests_beside_news_or_verbless_stay(
    text: str, kind: str, item: str, recipient: str
) -> None:
    frame = _lee(text)
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [(kind, item, recipient)], frame
