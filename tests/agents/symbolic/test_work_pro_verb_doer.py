"""Issue #23, fixer fix143b class 2: "need my sample tested before we can it tomorrow, can zosia
run it": a colleague asked with a request's modal and a verb that stands for the work named
before ("run it", "do it", "sort it", "deal with it": ``work_pro_verb``) is asked to do that
work, as "can Zosia test it" is (``named_doer``): a keeper of a facility that offers it does it
(Zosia, the nickname of Zofia, not the lab's first keeper); anyone else is said not to and
asked about. "before we can it" (to put in cans) is when, no modal."""

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
        # the class's analogue, in a small brewery
        ("need my sample tested before we can it tomorrow, can zosia run it", "zofia"),
        # variants of our own: the product or the operation's noun named, other pro-verbs
        ("need a test on my sample before we can it, can Zosia run it", "zofia"),
        ("need a lab report on my sample, can Tomek run it", "tomek"),
        ("my sample needs testing, could Tomasz handle it?", "tomek"),
        ("need my sample tested, can zofia do it", "zofia"),
    ],
)
def test_the_colleague_asked_to_run_it_does_the_work(text: str, doer: str) -> None:
    frame = _brew(text)
    assert [(t.operation, t.item, t.owner, t.recipient, t.actor) for t in frame.tasks] == [
        ("test", "sample", "ines", "ines", doer)
    ], frame


@pytest.mark.parametrize(
    ("text", "item", "doer"),
    [
        # the class's analogues on harbour (its laminator takes a badge, Sue and Max keep
        # it; Mark and Faith keep the scanner)
        ("need my badge laminated before the meeting, can Sue do it", "badge", "sue"),
        ("need a scan of my form, can Mark run it", "document", "mark"),
        ("need a scan of my form, can Faith sort it", "document", "faith"),
        ("need a scan of my form, could Faith deal with it", "document", "faith"),
    ],
)
def test_harbour_keeper_asked_to_do_it(text: str, item: str, doer: str) -> None:
    frame = _harbour(text)
    assert [(t.item, t.owner, t.recipient, t.actor) for t in frame.tasks] == [
        (item, "will", "will", doer)
    ], frame


def test_one_who_keeps_no_such_facility_is_said_not_to_and_asked() -> None:
    frame = _harbour("need a scan of my form, can Rose do it")
    assert frame.tasks == [], frame
    assert frame.question is not None and "doesn't look after the scanner" in frame.question


def test_run_to_the_shop_is_no_work_referred_to() -> None:
    # neighbour: "run" with no "it" is an errand outside, declined as before
    frame = _harbour("can Rose run to the shop")
    assert frame.tasks == [], frame


def test_without_a_named_doer_the_keepers_do_it() -> None:
    # neighbour: no one asked, the work is done at the lab by its keepers (no actor fixed)
    frame = _brew("need my sample tested before we can it tomorrow")
    assert [(t.operation, t.actor) for t in frame.tasks] == [("test", None)], frame


async def test_end_to_end_zosia_tests_the_sample_and_it_comes_back() -> None:
    text = "need my sample tested before we can it tomorrow, can zosia run it"
    run = await run_instruction(brewhouse(), "ines", text)
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    asked = [getattr(r.action, "contact", None) for r in run.stm.trace.actions()]
    assert "zofia" in asked and "tomek" not in asked, run.stm.trace.summary
    handed = [(e.detail["item"], e.detail["to"]) for e in run.sim.world.handovers()]
    assert ("lab_report:ines", "ines") in handed, run.stm.trace.summary
