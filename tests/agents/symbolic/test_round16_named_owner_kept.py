"""A named owner's item comes from that owner (blind round 16's class 1; the round's office and
sentences were never read). A lowercase possessive of a name with diacritics ("åsa's",
"bjørn's", "ramón’s"), softened as "any chance I could nab ...", restated by another name of
the item ("the telephoto i mean") and with a contrastive "not his camera", keeps the owner:
the owner is asked for their own long lens, never anyone else's fetched instead."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.core.actions import Inquire
from helpers.gazette import newsroom
from helpers.reading import answered_reader

_frame = answered_reader(newsroom, "ines")


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        (
            "any chance i could nab bjørn's long lens for tonight? the telephoto i mean, not "
            "his camera",
            "bjorn",
        ),
        ("any chance i could nab åsa's long lens? the telephoto i mean, not her camera", "asa"),
        ("any chance i could grab Ramón’s long lens?", "ramon"),
        ("is there any chance i could borrow łukasz's long lens", "lukasz"),
        ("any chance of zoë's camera?", "zoe"),
        ("ramón's long lens please, the telephoto, not his camera", "ramon"),
        ("could i borrow Bjørn’s long lens, not his camera", "bjorn"),
        ("could i borrow bjorn's long lens", "bjorn"),
        ("can i nab åsa's telephoto for tonight", "asa"),
    ],
)
def test_the_named_owner_is_kept(text: str, owner: str) -> None:
    frame = _frame(text)
    assert frame.question is None and frame.decline is None
    wanted = "camera" if "camera?" in text else "long_lens"
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", wanted, owner, "ines")
    ]
    # "not his camera" excludes the camera, never the owner's long lens
    assert owner not in frame.unusable(wanted)


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("any chance i could nab a long lens?", "long_lens"),
        ("any chance you could bring me a camera?", "camera"),
    ],
)
def test_anyones_item_stays_anyones(text: str, item: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.owner) for t in frame.tasks] == [("transfer", item, None)]


@pytest.mark.parametrize(
    "text",
    [
        "any chance Åsa has a long lens?",
        "is there any chance the printer works?",
        "thanks for bjørn's long lens",
        "does bjørn still have his long lens?",
    ],
)
def test_no_request_moves_nothing(text: str) -> None:
    assert _frame(text).tasks == []


async def test_the_owner_is_asked_and_nobody_else() -> None:
    run = await run_instruction(
        newsroom(),
        "ines",
        "any chance i could nab bjørn's long lens for tonight? the telephoto i mean, not his "
        "camera",
    )
    acted = [r.action for r in run.stm.trace.actions() if not r.refused]
    asked = {a.contact for a in acted if isinstance(a, Inquire)}
    assert asked <= {"bjorn", "ines"} and "bjorn" in asked
    moved = {e.detail["item"] for e in run.sim.world.handovers()}
    assert moved <= {"long_lens:bjorn"}
