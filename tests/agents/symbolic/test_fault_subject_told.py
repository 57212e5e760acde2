"""A sentence that reports a fault is context, whatever its first word: "Drive in slot 4 on
R12 has died. Can you bring me a spare from stores?" was declined as "an errand outside the
office" ("drive" is also a verb of leaving the building), then as a service nobody offers;
"Print queue 3 is jammed. Can you bring me paper?" printed the requester's file. A word
followed, before any join, by "has/is" and a broken thing's state is the subject of a
report; the request after it is read on its own, and "from <a facility's synonym>" names the
office's facility. The test office is the default one with a spares cupboard called "stores"
that keeps paper for anyone."""

from __future__ import annotations

import functools

import pytest

from assistantx.core.office import Office, parse_office
from helpers.dataset_offices import DEFAULT_FILE, harbour_office
from helpers.reading import frame_reader
from helpers.yaml_files import raw_yaml


@functools.cache
def _with_stores() -> Office:
    raw = raw_yaml(DEFAULT_FILE)
    raw["facilities"].append(
        {
            "id": "spares_cupboard",
            "name": "spares cupboard",
            "synonyms": ["stores"],
            "location": "print_room",
            "guards": ["mao"],
            "supplies": [{"type": "paper"}],
        }
    )
    return parse_office(raw)


_stores = frame_reader(_with_stores, "lin")
_harbour = frame_reader(harbour_office, "will")


@pytest.mark.parametrize(
    "text",
    [
        "Drive in slot 4 on R12 has died. Can you bring me paper from stores?",
        "Printer tray 2 on floor 3 has died. Can you bring me paper from stores?",
        "Print queue 3 is jammed. Can you bring me paper from stores?",
        "Drive 2 on the server is broken. Could you get me some paper?",
    ],
)
def test_a_fault_report_is_context_for_the_request_after_it(text: str) -> None:
    frame = _stores(text)
    assert frame.decline is None, frame.decline
    assert frame.question is None, frame.question
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", "paper", "lin")]


def test_the_same_on_harbour() -> None:
    frame = _harbour("Drive 2 on the server has died. Can you bring me a notepad from supplies?")
    assert frame.decline is None, frame.decline
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("produce", "notepad", "will")]


@pytest.mark.parametrize(
    "text",
    [
        "can you pick up paper from the shop on the corner",
        "drive over to the client's office and pick up their contract",
    ],
)
def test_an_errand_outside_is_still_declined(text: str) -> None:
    """Neighbours: a shop outside, and "drive" as the command it is."""
    frame = _stores(text)
    assert frame.tasks == []
    assert frame.decline is not None and "outside the office" in frame.decline


@pytest.mark.parametrize(
    "text", ["print my report the printer on floor 2 is broken", "print the page that's jammed"]
)
def test_a_verb_with_its_object_stays_a_command(text: str) -> None:
    """Neighbour: "print my report ..." is a command though a fault is said after it."""
    assert [t.kind for t in _stores(text).tasks] == ["print"]
