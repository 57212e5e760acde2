"""Issue #23, fixer fix151c class 2: the requester's own thing, which the office's data say
they hold, said fetched for them and then worked on ("get my form, then photocopy it for me",
"get my tech pack for me, then scan it") is collected from them for the work, which hands it
back with what it makes (``collected_own``). Before, the fetch of a thing to the one who has
it asked "Where is your document? As far as I know you have it with you.", and an answer
naming the thing again failed."""

from __future__ import annotations

from typing import Any

import pytest
from symbolic_run import run_instruction

from assistantx.core.office import load_office, parse_office
from helpers.atelier import atelier, raw_atelier
from helpers.dataset_offices import harbour_office
from helpers.reading import frame_reader

_default = frame_reader(load_office, "lee")
_harbour = frame_reader(harbour_office, "will")
_atelier = frame_reader(atelier, "mara")


@pytest.mark.parametrize(
    "text",
    [
        "get my form, then photocopy it for me",
        "get my contract for me, then photocopy it",
        "could you fetch my report then copy it for me",
    ],
)
def test_default_office_my_paper_collected_for_the_copy(text: str) -> None:
    frame = _default(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("copy", "document", "lee", "lee")
    ], frame


def test_harbour_my_form_collected_for_the_scan() -> None:
    frame = _harbour("get my form for me, then scan it")
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("document", "will", "will")
    ], frame
    assert frame.question is None, frame


def test_atelier_my_tech_pack_collected_for_the_photocopy() -> None:
    frame = _atelier("get my tech pack, then photocopy it for me")
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("copy", "spec_sheet", "mara", "mara")
    ], frame


def _unknown_spec_sheet() -> Any:
    # Mara's spec sheet is hers, but where it is nobody knows
    raw = raw_atelier()
    mara = next(p for p in raw["people"] if p["id"] == "mara")
    mara["owns"] = [{"type": "spec_sheet", "known": False}, {"type": "pattern_file"}]
    return parse_office(raw, raw["name"])


@pytest.mark.parametrize(
    ("read", "text"),
    [
        # neighbours: a thing nobody is known to hold; a colleague's part the office has no
        # word for ("initialled by Wang"); a copy for someone else (the original's way back
        # is not said)
        (frame_reader(_unknown_spec_sheet, "mara"), "get my tech pack, then photocopy it for me"),
        (_default, "get my form initialled by Wang then copy it for me"),
        (_default, "get my form then photocopy it for Wang"),
        (_default, "get my form for me"),
    ],
)
def test_still_asked(read: Any, text: str) -> None:
    frame = read(text)
    assert frame.tasks == [] and frame.question is not None, frame


async def test_end_to_end_collected_copied_and_handed_back() -> None:
    run = await run_instruction(atelier(), "mara", "get my tech pack, then photocopy it for me")
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    handed = {(e.detail["item"], e.detail["to"]) for e in run.sim.world.handovers()}
    assert {("spec_sheet:mara", "mara"), ("copy:mara", "mara")} <= handed, handed
