"""After a colleague's need of a thing, "run/pop/nip mine over/across/round to her" is the
speaker's own thing of that type, given to her: one transfer, never another colleague's thing
taken for the need besides, nor a thing read from the need's purpose ("for the bids")
(fix180a class 4)."""

from __future__ import annotations

from typing import Any

import pytest

from assistantx.core.office import load_office
from helpers.dataset_offices import harbour_office
from helpers.reading import frame_reader

_zhang = frame_reader(load_office, "zhang")
_lee = frame_reader(load_office, "lee")
_may = frame_reader(harbour_office, "may")


@pytest.mark.parametrize(
    ("read", "text", "item", "owner", "recipient"),
    [
        (
            _zhang,
            "Wang needs a stapler for the bids, can you run mine over to her",
            "stapler",
            "zhang",
            "wang",
        ),
        (
            _lee,
            "Wang needs a stapler for the bids, can you run mine over to her",
            "stapler",
            "lee",
            "wang",
        ),
        (
            _may,
            "June needs tape for the parcels, can you pop mine over to her",
            "tape",
            "may",
            "june",
        ),
        (
            _may,
            "June needs tape for the labels, can you nip mine across to her",
            "tape",
            "may",
            "june",
        ),
        (_may, "nip my ruler round to Mark", "ruler", "may", "mark"),
        # must not change: the giving verbs said plainly
        (
            _zhang,
            "Wang needs a stapler for the bids, can you bring mine to her",
            "stapler",
            "zhang",
            "wang",
        ),
        (_zhang, "can you run my stapler over to Wang", "stapler", "zhang", "wang"),
    ],
)
def test_mine_run_over_to_the_needer_is_one_transfer(
    read: Any, text: str, item: str, owner: str, recipient: str
) -> None:
    frame = read(text)
    assert frame.decline is None and frame.question is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", item, owner, recipient)
    ], frame
