"""A statement that the speaker has already dealt with their own thing is words: "my laptop's
flat, I've stuck it on charge in the copy room", "my stapler's playing up, I've left it in the
drawer". After the name of one of the office's things, "'s" before an adjective or a verb's
"-ing" that ends its clause is "is" (``screen.contracted_is``): a thing owns no "flat" and no
"playing", so nothing is asked about whose it is or who should get it. A request beside the
state ("my laptop's flat, can you charge it") is still done, and a noun after the "'s" is
still a part of the thing."""

from __future__ import annotations

import functools
from typing import Any

import pytest
from _offices import parser, tasks_of

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import parse_office
from helpers.dataset_offices import HARBOUR_FILE
from helpers.yaml_files import raw_yaml


@functools.cache
def _charging() -> InstructionParser:
    """Harbour with laptops and a charging dock in the copy room."""
    raw: dict[str, Any] = raw_yaml(HARBOUR_FILE)
    raw["item_types"].append({"id": "laptop", "name": "laptop", "kind": "personal"})
    raw["operations"].append(
        {"id": "charge", "name": "charge", "verbs": ["charge", "recharge"], "input": "laptop"}
    )
    raw["facilities"].append(
        {
            "id": "charging_dock",
            "name": "charging dock",
            "location": "copy_room",
            "operations": ["charge"],
            "guards": ["pat"],
        }
    )
    for p in raw["people"]:
        if p["id"] in ("may", "mark"):
            p["owns"].append({"type": "laptop", "known": True})
    return InstructionParser(parse_office(raw, "harbour with a charging dock"))


@pytest.mark.parametrize(
    "text",
    [
        "my laptop's flat, I've stuck it on charge in the copy room",
        "my laptop's flat, I've plugged it in at my desk",
        "my laptop's useless, I've left it with Mark",
        "my ruler's bent, I've left it by the printer",
    ],
)
def test_a_state_and_what_was_done_with_it_is_words_harbour(text: str) -> None:
    frame = _charging().parse(text, "may")
    assert frame.tasks == [] and frame.question is None and frame.decline, frame


@pytest.mark.parametrize(
    "text",
    [
        "my stapler's jammed, I've left it by the printer",
        "my stapler's playing up, I've stuck it in the drawer",
        "my book's falling apart, I've taped it up",
        "my data cable's faulty, I've put it back in my drawer",
    ],
)
def test_a_state_and_what_was_done_with_it_is_words_default(text: str) -> None:
    frame = parser("default").parse(text, "zhang")
    assert frame.tasks == []
    assert frame.question is None and frame.decline, frame


def test_a_request_beside_the_state_is_still_done() -> None:
    frame = _charging().parse("my laptop's flat, can you charge it", "may")
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("heat", "laptop", "may", "may")
    ]
    assert tasks_of("default", "my stapler's playing up, bring me Wang's", "zhang") == [
        ("transfer", "stapler", "wang", "zhang")
    ]


def test_a_persons_s_before_a_state_word_is_read_as_before() -> None:
    # "Wang's flat": Wang is no thing of the office, so the "'s" is not read as "is" here
    frame = parser("default").parse("my stapler's jammed, bring me Wang's", "zhang")
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "stapler", "wang", "zhang")
    ]
