"""Issue #23, fixer fix143b class 2 (second part): "need an ABV on my sample before we can it
tomorrow, can zosia run it", where the office has no word for an ABV: the keeper asked to
"run it" keeps a lab whose one operation on a beer sample is a test, so the test is asked of
them on the requester's sample (``keeper_asked_work``); the product comes back to the
requester. Before, the reader asked whom to give the sample to."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from helpers.brewhouse import brewhouse
from helpers.dataset_offices import harbour_office
from helpers.reading import frame_reader

_brew = frame_reader(brewhouse, "ines")
_harbour = frame_reader(harbour_office, "will")


@pytest.mark.parametrize(
    ("text", "doer"),
    [
        ("need an ABV on my sample before we can it tomorrow, can zosia run it", "zofia"),
        ("need a gravity reading on my sample, can Tomek run it?", "tomek"),
    ],
)
def test_the_keepers_work_on_my_thing(text: str, doer: str) -> None:
    frame = _brew(text)
    assert [(t.operation, t.item, t.owner, t.recipient, t.actor) for t in frame.tasks] == [
        ("test", "sample", "ines", "ines", doer)
    ], frame


def test_harbour_scanner_keeper_asked_to_run_it_on_my_form() -> None:
    frame = _harbour("need a quick pass on my form, can Faith run it")
    assert [(t.item, t.owner, t.recipient, t.actor) for t in frame.tasks] == [
        ("document", "will", "will", "faith")
    ], frame


@pytest.mark.parametrize(
    ("text", "reader"),
    [
        # neighbours: one who keeps nothing that works on a sample; no need said
        ("need an ABV on my sample, can Kemi run it", "brew"),
        ("got my badge here, can Max sort it", "harbour"),
    ],
)
def test_no_keepers_work_is_picked_otherwise(text: str, reader: str) -> None:
    frame = (_brew if reader == "brew" else _harbour)(text)
    assert frame.tasks == [] and frame.question is not None, frame


async def test_end_to_end_the_abv_is_zosias_test() -> None:
    text = "need an ABV on my sample before we can it tomorrow, can zosia run it"
    run = await run_instruction(brewhouse(), "ines", text)
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    handed = [(e.detail["item"], e.detail["to"]) for e in run.sim.world.handovers()]
    assert ("lab_report:ines", "ines") in handed, run.stm.trace.summary
