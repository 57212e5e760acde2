"""An item's name with a possessive word ("tailor's tape", "carpenter's rule") written without
its apostrophe ("anyone got a tailors tape?") is that name: the lexicon keeps the "word+s"
spelling of such a name beside it (``reading.lexicon``). On main the words matched nothing,
and the reader took the request's purpose ("to check a blazer size") for the thing asked.
Neighbours: the name with its apostrophe and the item's own name read as before."""

from __future__ import annotations

import functools

import pytest

from assistantx.core.office import Office, parse_office
from helpers.dataset_offices import DEFAULT_FILE, HARBOUR_FILE
from helpers.reading import frame_reader
from helpers.yaml_files import raw_yaml


@functools.cache
def _harbour_tailored() -> Office:
    """Harbour (whose tape dispenser is also "tape") with a tape measure Rose keeps, also
    called "tailor's tape", and its ruler also called "carpenter's rule"."""
    raw = raw_yaml(HARBOUR_FILE)
    raw["item_types"].append(
        {
            "id": "tape_measure",
            "name": "tape measure",
            "synonyms": ["tailor's tape", "measuring tape"],
            "purposes": ["measure"],
        }
    )
    rose = next(p for p in raw["people"] if p["id"] == "rose")
    rose["owns"].append({"type": "tape_measure", "known": True})
    ruler = next(t for t in raw["item_types"] if t["id"] == "ruler")
    ruler["synonyms"] = [*ruler.get("synonyms", []), "carpenter's rule"]
    return parse_office(raw)


@functools.cache
def _default_tailored() -> Office:
    """The default office with a tape measure Zhou keeps, also called "tailor's tape"."""
    raw = raw_yaml(DEFAULT_FILE)
    raw["item_types"].append(
        {
            "id": "tape_measure",
            "name": "tape measure",
            "synonyms": ["tailor's tape", "measuring tape"],
            "purposes": ["measure"],
        }
    )
    zhou = next(p for p in raw["people"] if p["id"] == "zhou")
    zhou["owns"].append({"type": "tape_measure", "known": True})
    return parse_office(raw)


_harbour = frame_reader(_harbour_tailored, "may")
_default = frame_reader(_default_tailored, "lin")


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("could you bring me a tailors tape to check a blazer size", "tape_measure"),
        ("can i borrow a tailors tape pls", "tape_measure"),
        ("could you bring me a carpenters rule", "ruler"),
        ("can i borrow a carpenters rule for a sec", "ruler"),
        ("could you bring me a tailor's tape", "tape_measure"),  # neighbour: apostrophe
        ("could you bring me some tape", "tape"),  # neighbour: the dispenser's own name
    ],
)
def test_harbour_a_name_said_without_its_apostrophe_is_that_name(text: str, item: str) -> None:
    frame = _harbour(text)
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", item, "may")], (
        frame
    )


def test_harbour_asking_whether_anyone_has_one_asks_for_that_thing() -> None:
    frame = _harbour("anyone got a tailors tape? to check a blazer size")
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("transfer", "tape_measure", "may")
    ], frame


@pytest.mark.parametrize(
    "text", ["can i borrow a tailors tape pls", "could you bring me a tailors tape"]
)
def test_default_a_tailors_tape_is_the_tape_measure(text: str) -> None:
    frame = _default(text)
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("transfer", "tape_measure", "lin")
    ], frame
