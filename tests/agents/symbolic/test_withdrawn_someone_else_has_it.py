"""A request withdrawn in a later sentence that also says someone else has the thing or is
bringing it (blind rounds 20 to 22's class, on a conservation department no sentence was
written for, ``helpers.conservation_lab``): "bring me a battery. actually no forget it,
Joss's got a spare on his desk" drops the request in words and moves nothing (on main "no
forget it" went unread as a withdrawal and a battery was fetched), and so does "... never
mind, Otto's bringing it up" (on main the reason said in the progressive was left as the
request and asked about). Without a withdrawal, who has one is where to get it: still done."""

from __future__ import annotations

import pytest

from helpers.conservation_lab import conservation_lab
from helpers.reading import frame_reader

_frame = frame_reader(conservation_lab, "nell")


@pytest.mark.parametrize(
    "text",
    [
        "bring me a battery. actually no forget it, Joss's got a spare on his desk",
        "bring me a battery. no forget it, Mina's got one for me",
        "can you get me a battery? nah never mind, Bea has a spare",
        "fetch my sample tray from the cold store. actually never mind, Otto's bringing it up",
        "fetch my sample tray from the walk-in. never mind, Otto is bringing it up",
        "fetch my sample tray please. forget it, Joss will bring it over later",
        "could you grab me a checklist? actually never mind, Bea's printing me one",
        "charge me a battery please. actually forget it, Mina's already on it",
        # "wait" before a withdrawal only stresses it (blind round 24's default office)
        "bring me a battery. oh wait never mind, Joss just gave me one",
        "can you get me a battery? wait, never mind",
    ],
)
def test_withdrawn_with_someone_else_on_it_moves_nothing(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and "did nothing" in frame.decline


@pytest.mark.parametrize(
    "text",
    [
        "bring me a battery, Joss's got a spare on his desk",
        "bring me a battery please. Joss has a spare on his desk",
        "bring me a battery please, wait for me at my desk",
    ],
)
def test_who_has_one_without_a_withdrawal_is_still_done(text: str) -> None:
    frame = _frame(text)
    assert frame.decline is None, frame
    assert [t.item for t in frame.tasks] == ["battery"] or frame.question is not None, frame


@pytest.mark.parametrize(
    ("text", "item"),
    [
        (
            "fetch my sample tray. never mind, Otto's bringing it up. bring me a checklist",
            "checklist",
        ),
        ("bring me a battery. no forget it, just bring me Bea's checklist", "checklist"),
    ],
)
def test_a_request_after_the_withdrawal_is_still_read(text: str, item: str) -> None:
    frame = _frame(text)
    assert [t.item for t in frame.tasks] == [item], frame
