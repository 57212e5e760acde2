"""The consent guard tells namesakes apart by spelling as the reader does, and reads "<name>'s
after my Y" as a wish for the requester's own thing (fix154a class 2: "Sofía's after my loan
form, can you take it to her?", with Sofía Ramírez and Sofia Kowalczyk in the office, was read
by the reader as a delivery to Sofía Ramírez and refused by the guard: "Sofía Ramírez is not
someone you named to receive or work on it"). "Sofía" typed with its mark is the one who
spells it so; "Sofia" without any mark says nothing of which (both may be meant, and the
reader asks). A wish about the time ("after the meeting") or another's thing names nobody."""

from __future__ import annotations

import copy
import functools
from typing import Any

import pytest
import yaml

from assistantx.core.office import Office, parse_office
from assistantx.runtime.recipients import named_recipients
from helpers.consent_memory import memory
from helpers.dataset_offices import DEFAULT_FILE, HARBOUR_FILE, default_office, harbour_office
from helpers.reading import frame_reader


def _renamed(path: Any, names: dict[str, str], title: str) -> Office:
    raw: dict[str, Any] = copy.deepcopy(yaml.safe_load(path.read_text(encoding="utf-8")))
    for p in raw["people"]:
        if p["id"] in names:
            p["name"], p["aliases"] = names[p["id"]], []
    return parse_office(raw, title)


@functools.cache
def _sofias() -> Office:
    # the default office's wang and zhang renamed: two Sofias, one with the accent
    return _renamed(
        DEFAULT_FILE, {"wang": "Sofía Ramírez", "zhang": "Sofia Kowalczyk"}, "two sofias"
    )


@functools.cache
def _renees() -> Office:
    return _renamed(HARBOUR_FILE, {"grace": "Renée Dubois", "hope": "Renee Park"}, "two renees")


@pytest.mark.parametrize(
    "text",
    [
        "Sofía's after my stapler, can you take it to her?",
        "Sofía wants my scissors, could you take them to her",
        "Sofía needs my stapler, can you take it to her",
        "Sofía's after my stapler, can you take it over",
    ],
)
def test_the_accented_namesake_is_named_to_receive(text: str) -> None:
    assert named_recipients(_sofias(), memory("lee", text)) == {"wang"}
    frame = frame_reader(_sofias, "lee")(text)
    assert [(t.kind, t.owner, t.recipient) for t in frame.tasks] == [("transfer", "lee", "wang")], (
        frame
    )


def test_the_same_in_harbour_with_two_renees() -> None:
    text = "Renée's after my calculator, can you take it to her?"
    assert named_recipients(_renees(), memory("rose", text)) == {"grace"}


@pytest.mark.parametrize(
    ("office", "requester", "text", "named"),
    [
        (default_office, "lee", "Wang's after my stapler, can you take it to him?", {"wang"}),
        (default_office, "lee", "Wang's after my stapler, can you take it over", {"wang"}),
        (harbour_office, "rose", "Grace's after my calculator, can you bring it over", {"grace"}),
    ],
)
def test_after_my_thing_names_the_one_who_wants_it(
    office: Any, requester: str, text: str, named: set[str]
) -> None:
    assert named_recipients(office(), memory(requester, text)) == named


@pytest.mark.parametrize(
    "text",
    [
        "Wang's after the meeting, can you take it over",  # a time, no wish
        "Wang's after Zhang's stapler, can you take it over",  # another's thing
    ],
)
def test_after_no_thing_of_mine_names_nobody(text: str) -> None:
    assert named_recipients(default_office(), memory("lee", text)) == set()


def test_the_unaccented_name_stays_both() -> None:
    named = named_recipients(_sofias(), memory("lee", "take my stapler to Sofia"))
    assert named == {"wang", "zhang"}


def test_dont_give_it_to_her_delivers_nothing() -> None:
    frame = frame_reader(default_office, "lee")("Wang's after my stapler, don't give it to him")
    assert frame.tasks == [], frame
