"""A keeper agrees to the work their facility runs when the thing it makes is named like the
work (blind round 139's class 2): an office whose scan makes an electronic "scan" (a PDF sent
by message) had every guard answer "could you scan Nadia Haddad's form ...?" with "Sorry, I
don't have Nadia Haddad's form": the simulated colleague read "scan" as the name of a thing
and lost the verb, because only items of kind ``product`` were held aside as what the office
makes. What an operation makes is its product whatever its kind. Checked on a test print
room (print, copy, scan, laminate, bind, shred), the default office and harbour with a scan
that makes a PDF."""

from __future__ import annotations

from typing import Any

import pytest
from symbolic_run import run_instruction

from assistantx.core.office import Office, parse_office
from assistantx.sim.people import direct_reply, group_replies
from assistantx.sim.world import World
from helpers.dataset_offices import HARBOUR_FILE, default_office_that_scans, raw_yaml
from helpers.scanning_room import paper_scanning_room, scanning_room

_ASKED = (
    "Hi Lucy, could you {verb} Nadia Haddad's form at the print room? The robot will come to "
    "you for the hand-over."
)


@pytest.mark.parametrize("office", [scanning_room, paper_scanning_room])
@pytest.mark.parametrize(
    ("verb", "operation"),
    [
        ("scan", "scan"),
        ("copy", "copy"),
        ("print", "print"),
        ("laminate", "laminate"),
        ("bind", "bind"),
        ("shred", "shred"),
    ],
)
def test_the_guard_agrees_to_each_operation_the_room_runs(
    office: Any, verb: str, operation: str
) -> None:
    reply = direct_reply(World.from_office(office()), "lucy", _ASKED.format(verb=verb))
    assert reply is not None and reply.text.startswith(f"Yes, I can do that ({operation})")


def test_a_colleague_who_runs_no_scan_still_says_no() -> None:
    # only the room's guards run it (on main Omar answered about a form of his own)
    asked = "Hi Omar, could you scan Nadia Haddad's form at the print room?"
    reply = direct_reply(World.from_office(scanning_room()), "omar", asked)
    assert reply is not None and reply.text.startswith("Sorry, I can't help with that (scan)")


def test_only_the_guards_volunteer_in_the_group() -> None:
    office = scanning_room()
    asked = "Hi all, could anyone scan Nadia Haddad's form at the print room?"
    everyone = [p.id for p in office.people]
    replies = group_replies(World.from_office(office), everyone, asked)
    assert sorted(r.person for r in replies) == ["lucy", "raj"]


def test_a_thing_that_is_no_product_is_still_answered_as_a_thing() -> None:
    # must not change: the form the scan works on is a thing, asked about as one
    asked = "Hi Lucy, could you lend Nadia Haddad your form?"
    reply = direct_reply(World.from_office(scanning_room()), "lucy", asked)
    assert reply is not None and reply.text == "No, I don't have a form."


def _harbour_scanning_to_pdf() -> Office:
    """Harbour whose scanner's scan is a PDF (an electronic item named "scan")."""
    raw = raw_yaml(HARBOUR_FILE)
    scan = next(t for t in raw["item_types"] if t["id"] == "scan")
    scan.update({"kind": "electronic", "name": "scan", "synonyms": ["PDF"]})
    op = next(o for o in raw["operations"] if o["id"] == "scan")
    op["done"] = "scanned to PDF"
    return parse_office(raw)


def _default_scanning_to_pdf() -> Office:
    return default_office_that_scans("scan", {"id": "scan", "name": "scan", "synonyms": ["PDF"]})


@pytest.mark.parametrize(
    ("office", "guard", "asked"),
    [
        (
            _default_scanning_to_pdf,
            "xu",
            "Hi Xu, could you scan Lee Ming's document to PDF at the printer?",
        ),
        (
            _harbour_scanning_to_pdf,
            "faith",
            "Hi Faith, could you scan May Okafor's document at the scanner?",
        ),
    ],
)
def test_the_dataset_offices_scanner_guards_agree(office: Any, guard: str, asked: str) -> None:
    # on main these said yes only by answering about a document of their own
    reply = direct_reply(World.from_office(office()), guard, asked)
    assert reply is not None and reply.text.startswith("Yes, I can do that (scan)")


@pytest.mark.parametrize(
    ("office", "requester", "text"),
    [
        (scanning_room, "nadia", "Can you get my booking form scanned to PDF?"),
        (scanning_room, "omar", "could you scan my form to PDF please"),
        (scanning_room, "nadia", "can you get my form laminated?"),
        (scanning_room, "nadia", "please bind my booking form"),
        (_default_scanning_to_pdf, "lee", "Can you get my document scanned to PDF?"),
        (_harbour_scanning_to_pdf, "may", "could you scan my document to PDF?"),
    ],
)
async def test_the_work_is_done(office: Any, requester: str, text: str) -> None:
    run = await run_instruction(office(), requester, text)
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
