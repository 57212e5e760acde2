"""Work nothing here does on the speaker's own thing, said by a verb the reader has no rule
for, is declined by name whatever the thing is ("can you engrave my ring for the customer",
round 237's "dye my trousers navy for the customer"): a thing the office does not list was
asked about as a request nobody understood, or as a thing for an outsider, and "my trousers
navy" read "navy" as the noun "trousers" modified, so the office's own garment was missed. A
colour after a thing's name says its colour, no compound's head."""

from __future__ import annotations

import pytest

from assistantx.core.office import load_office
from helpers.reading import frame_reader

_frame = frame_reader(load_office, "lee")


@pytest.mark.parametrize(
    ("text", "verb"),
    [
        ("can you polish my boots", "polish"),
        ("can u engrave my ring", "engrave"),
        ("can u engrave my ring for the customer", "engrave"),
        ("could you dye my jumper for the client", "dye"),
        ("can you paint my mug navy", "paint"),
        ("can you paint my mug navy for the party", "paint"),
        ("pls dye my mug charcoal", "dye"),
    ],
)
def test_work_nothing_here_does_on_ones_own_thing_is_declined(text: str, verb: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and f"I can't {verb}" in frame.decline, frame


@pytest.mark.parametrize(
    ("text", "item", "owner", "recipient"),
    [
        ("can you grab Zhang's stapler for me", "stapler", "zhang", "lee"),  # a known errand verb
        ("bring me the navy mug", "cup", None, "lee"),  # a colour before the name
        ("can you take my stapler to Wang", "stapler", "lee", "wang"),
    ],
)
def test_errands_and_colours_before_a_name_read_as_before(
    text: str, item: str, owner: str | None, recipient: str
) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", item, owner, recipient)
    ], frame


def test_a_colour_after_a_name_is_no_compound_head() -> None:
    frame = _frame("can you bring me Zhang's stapler, the navy one")
    assert [(t.item, t.owner) for t in frame.tasks] == [("stapler", "zhang")], frame
