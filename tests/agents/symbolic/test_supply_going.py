"""British "going" (spare) of a supply the office keeps for anyone is the speaker's want of one:
"is there any paper going?" was answered with where it is or who has one and an offer; for a
thing a facility supplies it is read as "can I have some paper?" is. A thing only colleagues
have stays a question answered with who has one and an offer (the consent rules ask them),
and "is anything going on?" (no thing) or a need for later stay as before."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import OfficeOf, frame_reader
from helpers.site_cabin import site_cabin

_WHO = {default_office: "lee", harbour_office: "will", site_cabin: "tamsin"}


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("is there any paper going?", "paper"),
        ("any paper going?", "paper"),
        ("any tape going spare?", "tape"),
        ("is there any duct tape going", "tape"),  # the supply by its synonym
    ],
)
def test_a_supply_going_is_wanted(text: str, item: str) -> None:
    frame = frame_reader(site_cabin, "tamsin")(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", item, "tamsin")]


@pytest.mark.parametrize(
    ("office", "text"),
    [
        (site_cabin, "is there a pen going?"),  # colleagues' pens: asked first
        (default_office, "is there any paper going?"),  # colleagues' paper: asked first
        (harbour_office, "is there any tape going?"),
    ],
)
def test_a_thing_only_colleagues_have_is_offered(office: OfficeOf, text: str) -> None:
    frame = frame_reader(office, _WHO[office])(text)
    assert frame.tasks == [] and frame.question is not None, frame
    assert "Shall I bring you" in frame.question, frame


@pytest.mark.parametrize(
    ("office", "text"),
    [
        (site_cabin, "is anything going on?"),
        (default_office, "is anything going on?"),
        (site_cabin, "any paper going tomorrow?"),  # for later: told, nothing moves
    ],
)
def test_no_supply_wanted_now_moves_nothing(office: OfficeOf, text: str) -> None:
    frame = frame_reader(office, _WHO[office])(text)
    assert frame.tasks == [], frame
