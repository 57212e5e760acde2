"""Fix129a, class 2 (analogues, not the measured sentences): a tool's declared name with a
possessive ("manager's stamp", "registrar's stamp", "harbourmaster's stamp") is one thing, and
the work it is named for is asked by naming it:

- "put the registrar's stamp on my invoice and then courier it to ..." stamps the invoice, then
  sends it (reading/named_tool.py: a clause that names the work's tool is work, not the
  context a later "it" clause drops);
- "this crew list needs the registrar's stamp on it" asks for the stamp, though "crew" is also
  the past of "crow" (reading/compound_subject.py: two nouns after a determiner before a
  need are one subject);
- "bring me Siobhan's stamp" where "stamp" is only the work's word fetches Siobhan's tool
  (reading/cued_tool.py), never any seal.

A possessive of a colleague before the tool's head noun is still whose ("bring me Wang's
stamp"); a tool only said to be somewhere is no work."""

from __future__ import annotations

import functools
from typing import Any

import pytest

from assistantx.core.office import Office, parse_office
from assistantx.core.task_schema import TaskFrame
from helpers.courier_room import raw_courier_room
from helpers.dataset_offices import DEFAULT_FILE, HARBOUR_FILE
from helpers.reading import frame_reader
from helpers.yaml_files import raw_yaml


@functools.cache
def _managers_default() -> Office:
    """The default office whose seal is called the "manager's stamp"."""
    raw: dict[str, Any] = raw_yaml(DEFAULT_FILE)
    next(t for t in raw["item_types"] if t["id"] == "seal")["name"] = "manager's stamp"
    return parse_office(raw, "manager's stamp")


@functools.cache
def _clerks_room() -> Office:
    """The courier room whose office stamp is only the "registrar's stamp" (no bare "stamp") and
    whose courier desk is the "agent's courier bag"."""
    raw = raw_courier_room()
    stamp = next(t for t in raw["item_types"] if t["id"] == "office_stamp")
    stamp["name"], stamp["synonyms"] = "registrar's stamp", []
    desk = next(f for f in raw["facilities"] if f["id"] == "courier_desk")
    desk["name"] = "agent's courier bag"  # a facility's name with a possessive too
    return parse_office(raw, "registrar's stamp")


@functools.cache
def _harbourmasters() -> Office:
    """Harbour with a seal called the "harbourmaster's stamp" that Mark and Will own."""
    raw: dict[str, Any] = raw_yaml(HARBOUR_FILE)
    raw["item_types"].append({"id": "seal", "name": "harbourmaster's stamp", "seals": True})
    for person in raw["people"]:
        if person["id"] in ("mark", "will"):
            person.setdefault("owns", []).append({"type": "seal", "known": True})
    return parse_office(raw, "harbourmaster's stamp")


_default = frame_reader(_managers_default, "lin")
_clerks = frame_reader(_clerks_room, "ana")
_harbour = frame_reader(_harbourmasters, "may")


def _tasks(frame: TaskFrame) -> list[tuple[str, str | None, str | None, str | None]]:
    assert frame.question is None and frame.decline is None, (frame.question, frame.decline)
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    ("read", "text", "tasks"),
    [
        # the class's analogues
        (_default, "put the manager's stamp on my contract", [("seal", "document", "lin", "lin")]),
        (
            _default,
            "my contract needs the manager's stamp on it, can you sort that?",
            [("seal", "document", "lin", "lin")],
        ),
        (
            _default,
            "could you put the manager's stamp on my report and then give it to Wang",
            [("seal", "document", "lin", "wang")],
        ),
        (
            _harbour,
            "put the harbourmaster's stamp on my invoice",
            [("seal", "document", "may", "may")],
        ),
        # neighbour: a colleague's possessive before the head noun is whose
        (_default, "bring me Wang's stamp", [("transfer", "seal", "wang", "lin")]),
        (_harbour, "bring me Mark's harbourmaster's stamp", [("transfer", "seal", "mark", "may")]),
    ],
)
def test_the_possessive_name_is_the_tool(
    read: Any, text: str, tasks: list[tuple[str, str | None, str | None, str | None]]
) -> None:
    assert _tasks(read(text)) == tasks


@pytest.mark.parametrize(
    "text",
    [
        "could you put the registrar's stamp on my invoice then courier it to Acme at Leeds Docks?",
        "put the registrar's stamp on my contract and courier it to Acme Ltd in Hull",
    ],
)
def test_the_named_tool_is_work_before_a_clause_on_it(text: str) -> None:
    frame = _clerks(text)
    assert frame.question is None, frame.question
    sealed, sent = frame.tasks
    assert (sealed.kind, sealed.item, sealed.owner) == ("seal", "document", "ana")
    assert (sent.item, sent.operation) == ("document", "courier")
    assert sent.destination is not None and sent.destination.startswith("Acme")


def test_a_tool_only_said_to_be_somewhere_is_no_work() -> None:
    frame = _clerks("the registrar's stamp is on my desk, courier my contract to Acme Ltd in Hull")
    assert [(t.item, t.operation) for t in frame.tasks] == [("document", "courier")]


@pytest.mark.parametrize(
    ("read", "text", "who"),
    [
        (
            _clerks,
            "This crew list needs the registrar's stamp on it, could you sort that out?",
            "ana",
        ),
        (
            _harbour,
            "This crew list needs the harbourmaster's stamp on it, could you sort that out?",
            "may",
        ),
        (_harbour, "the crew list needs stamping", "may"),
        (_default, "my crew rota needs the manager's stamp on it", "lin"),
    ],
)
def test_a_two_noun_subject_needs_the_stamp(read: Any, text: str, who: str) -> None:
    assert _tasks(read(text)) == [("seal", "document", who, who)]


def test_a_two_noun_subject_told_of_is_still_told() -> None:
    frame = _harbour("the crew list is on my desk")
    assert frame.tasks == [] and frame.decline is not None


@pytest.mark.parametrize(
    ("text", "owner"), [("bring me Siobhan's stamp", "siobhan"), ("bring me the stamp", None)]
)
def test_whose_tool_said_by_its_works_word(text: str, owner: str | None) -> None:
    assert _tasks(_clerks(text)) == [("transfer", "office_stamp", owner, "ana")]
