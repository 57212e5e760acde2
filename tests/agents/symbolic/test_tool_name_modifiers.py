"""Fix129a, class 1 (analogues, not the measured sentences): a word of one of the seal tool's
names that is a word of another item's names lends the tool no verb, and a lent form said
inside a name said whole is that name's word (reading/tool_verbs.py). Where the seal is a
"claims stamp" or an "approved stamp" and the papers are "claim forms", "claim" is the
paper's word ("bring me Lee's claim folder" never fetches the stamp), and "bring me the
approved stamp" fetches the stamp; the tool's head noun as a verb ("stamp my claim form")
and a verb no other item's name has ("get my contract approved") still ask for sealing."""

from __future__ import annotations

import functools
from typing import Any

import pytest

from assistantx.agents.symbolic.reading.tool_verbs import LentVerbs
from assistantx.core.office import Office, parse_office
from assistantx.core.task_schema import TaskFrame
from helpers.dataset_offices import DEFAULT_FILE, HARBOUR_FILE
from helpers.reading import frame_reader
from helpers.yaml_files import raw_yaml


def _with_claims(raw: dict[str, Any], owners: tuple[str, ...], seal: str) -> Office:
    """``raw`` whose seal (added where it has none) is also a claims and an approved stamp,
    and whose papers are also claim forms."""
    types = {t["id"]: t for t in raw["item_types"]}
    if "seal" not in types:
        raw["item_types"].append({"id": "seal", "name": "seal", "seals": True, "synonyms": []})
        types["seal"] = raw["item_types"][-1]
        for person in raw["people"]:
            if person["id"] in owners:
                person.setdefault("owns", []).append({"type": "seal", "known": True})
    types["seal"]["synonyms"] = [*types["seal"].get("synonyms", []), seal, "approved stamp"]
    types["document"]["synonyms"] = [*types["document"]["synonyms"], "claim form"]
    return parse_office(raw, "claims office")


@functools.cache
def _claims_default() -> Office:
    return _with_claims(raw_yaml(DEFAULT_FILE), (), "claims stamp")


@functools.cache
def _claims_harbour() -> Office:
    return _with_claims(raw_yaml(HARBOUR_FILE), ("mark", "will"), "rubber claims stamp")


_default = frame_reader(_claims_default, "lin")
_harbour = frame_reader(_claims_harbour, "may")


def _tasks(frame: TaskFrame) -> list[tuple[str, str | None, str | None, str | None]]:
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


def test_a_word_of_another_items_name_lends_no_verb() -> None:
    forms = LentVerbs.from_office(_claims_default(), ()).forms
    assert "claim" not in forms and "claimed" not in forms
    assert forms["approved"] == "sealed"  # no other item's name has "approved"


@pytest.mark.parametrize(
    ("read", "text"),
    [
        (_default, "bring me Lee's claim folder"),  # the class's analogue
        (_default, "I need Wang's claim folder from the cupboard"),
        (_harbour, "bring me Rose's claim folder"),
    ],
)
def test_a_thing_named_by_the_papers_word_is_not_the_seal(read: Any, text: str) -> None:
    frame = read(text)
    assert all(t.item != "seal" and t.kind != "seal" for t in frame.tasks), _tasks(frame)


@pytest.mark.parametrize(
    ("read", "text", "task"),
    [
        (_default, "hand my claim form to Wang", ("transfer", "document", "lin", "wang")),
        (
            _default,
            "Could you hand my claim form to Wang for checking?",
            ("transfer", "document", "lin", "wang"),
        ),
        (_harbour, "pass my claim form to Grace", ("transfer", "document", "may", "grace")),
        # the tool as a thing, by a name whose modifier is a lent verb
        (_default, "bring me the approved stamp", ("transfer", "seal", None, "lin")),
        (_harbour, "bring me the approved stamp", ("transfer", "seal", None, "may")),
        # neighbours: the tool's head noun as a verb, the tool as a thing, a verb still lent
        (_default, "stamp my claim form", ("seal", "document", "lin", "lin")),
        (_default, "bring me the claims stamp", ("transfer", "seal", None, "lin")),
        (_default, "get my contract approved", ("seal", "document", "lin", "lin")),
        (_harbour, "stamp my claim form", ("seal", "document", "may", "may")),
    ],
)
def test_claim_forms_and_the_claims_stamp(
    read: Any, text: str, task: tuple[str, str | None, str | None, str | None]
) -> None:
    frame = read(text)
    assert frame.question is None, frame.question
    assert _tasks(frame) == [task]
