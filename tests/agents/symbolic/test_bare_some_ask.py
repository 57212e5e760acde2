"""A bare ask for a supply opening with "Some"/"A few"/"Another" and naming where it is kept
("Some twine from the potting shed, please.") is a request for it (blind round 43-44's class
F3: a place's last word that is also a verb, "shed", was read as the statement's verb, and
nothing was done). A word right after an article, or the last word of the office's own name of
several words, is a noun there. A real statement about the supply stays a statement."""

from __future__ import annotations

import pytest

from helpers.nursery_yard import nursery_yard
from helpers.reading import frame_reader

_frame = frame_reader(nursery_yard, "ada")


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("Some twine from the potting shed, please.", "twine"),
        ("Some twine from the shed, please.", "twine"),
        ("some garden twine from the potting shed pls", "twine"),
        ("Some paper clips from the potting shed, please.", "clips"),
        ("A few paper clips from the potting shed, please", "clips"),
        ("Another paper clip from the shed, thanks", "clips"),
        ("Twine from the potting shed, please.", "twine"),
    ],
)
def test_a_bare_ask_for_a_supply_from_where_it_is_kept_is_a_request(text: str, item: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", item, "ada")], (
        frame
    )


@pytest.mark.parametrize(
    "text",
    [
        "Some twine fell off the shelf.",
        "Some twine is in the potting shed.",
        "Some twine from the potting shed fell off.",
        "Some paper clips fell behind the shed.",
    ],
)
def test_a_statement_about_the_supply_stays_a_statement(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [], frame
