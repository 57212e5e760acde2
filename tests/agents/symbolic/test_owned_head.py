"""The head noun of an item type's name, said with "my" or a colleague's possessive, names
that type when it is the owner's only thing ending in it (``screen.owned_head``): "take my
lamp to Rose" where the speaker owns an "inspection lamp", "can I borrow Mark's gauge" where
Mark owns a "tyre pressure gauge" (before: "I'm not sure what you need"). Two of the owner's
things ending in it are asked about ("your inspection lamp or your desk lamp?") and the
answer names which; an owner with no such thing keeps the old reading (asked). Offices built
here: harbour and the default office, each with a few types of several words added."""

from __future__ import annotations

import functools
from typing import Any

import pytest

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import Office, parse_office
from assistantx.core.task_schema import TaskFrame
from helpers.dataset_offices import DEFAULT_FILE, HARBOUR_FILE
from helpers.yaml_files import raw_yaml


def _with(file: Any, types: list[dict[str, Any]], owns: dict[str, list[str]], name: str) -> Office:
    raw: dict[str, Any] = raw_yaml(file)
    raw["item_types"] += types
    for p in raw["people"]:
        for type_id in owns.get(p["id"], []):
            p["owns"].append({"type": type_id, "known": True})
    return parse_office(raw, name)


_LAMP = {"id": "inspection_lamp", "name": "inspection lamp", "synonyms": ["work light", "torch"]}
_GAUGE = {"id": "pressure_gauge", "name": "tyre pressure gauge"}
_DESK_LAMP = {"id": "desk_lamp", "name": "desk lamp"}


@functools.cache
def _parser(which: str) -> InstructionParser:
    if which == "harbour":
        office = _with(
            HARBOUR_FILE,
            [_LAMP, _GAUGE],
            {"will": ["inspection_lamp"], "mark": ["pressure_gauge"]},
            "harbour workshop",
        )
    elif which == "two lamps":
        office = _with(
            HARBOUR_FILE,
            [_LAMP, _GAUGE, _DESK_LAMP],
            {"will": ["inspection_lamp", "desk_lamp"], "mark": ["pressure_gauge"]},
            "harbour, two lamps",
        )
    else:
        office = _with(
            DEFAULT_FILE,
            [
                {"id": "fan", "name": "desk fan", "synonyms": ["electric fan"]},
                {"id": "pointer", "name": "laser pointer"},
            ],
            {"lee": ["fan"], "chen": ["pointer"]},
            "default with a fan",
        )
    return InstructionParser(office)


def _read(which: str, text: str, who: str, answers: list[str] | None = None) -> TaskFrame:
    if answers is None:
        return _parser(which).parse(text, who)
    return _parser(which).parse_with_answers(text, who, answers)


def _tasks(frame: TaskFrame) -> list[tuple[str, str | None, str | None, str | None]]:
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    ("which", "who", "text", "expected"),
    [
        # the class's analogues
        ("harbour", "will", "take my lamp to Rose", [("inspection_lamp", "will", "rose")]),
        ("harbour", "pat", "can I borrow Mark's gauge", [("pressure_gauge", "mark", "pat")]),
        # variants of our own: a synonym's head, a colleague's, two parts, another office
        ("harbour", "will", "bring my light to Grace", [("inspection_lamp", "will", "grace")]),
        ("harbour", "pat", "can I borrow Will's lamp", [("inspection_lamp", "will", "pat")]),
        (
            "harbour",
            "mark",
            "take my gauge to Will and bring me a ruler",
            [("pressure_gauge", "mark", "will"), ("ruler", None, "mark")],
        ),
        ("default", "zhang", "could you bring me Lee's fan", [("fan", "lee", "zhang")]),
        ("default", "chen", "take my pointer to Wang", [("pointer", "chen", "wang")]),
    ],
)
def test_the_head_with_its_owner_names_the_owners_one_thing(
    which: str, who: str, text: str, expected: list[tuple[str, str | None, str]]
) -> None:
    frame = _read(which, text, who)
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == expected, (
        frame.question,
        frame.decline,
    )


@pytest.mark.parametrize(
    ("who", "text", "said"),
    [
        ("will", "take my lamp to Rose", "your inspection lamp or your desk lamp"),
        ("pat", "can I borrow Will's lamp", "inspection lamp or Will Tanaka's desk lamp"),
    ],
)
def test_two_of_the_owners_things_ending_in_it_are_asked(who: str, text: str, said: str) -> None:
    frame = _read("two lamps", text, who)
    assert frame.tasks == [], _tasks(frame)
    assert frame.question is not None and said in frame.question, frame.question


@pytest.mark.parametrize(
    ("who", "text", "answer", "expected"),
    [
        ("will", "take my lamp to Rose", "the desk lamp", ("desk_lamp", "will", "rose")),
        ("will", "take my lamp to Rose", "my inspection lamp", ("inspection_lamp", "will", "rose")),
        ("pat", "can I borrow Will's lamp", "the desk lamp", ("desk_lamp", "will", "pat")),
        ("pat", "can I borrow Will's lamp", "the desk one", ("desk_lamp", "will", "pat")),
        (
            "will",
            "take my lamp to Rose",
            "not the inspection lamp, the desk one",
            ("desk_lamp", "will", "rose"),
        ),
    ],
)
def test_the_answer_says_which(
    who: str, text: str, answer: str, expected: tuple[str, str, str]
) -> None:
    frame = _read("two lamps", text, who, [answer])
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [expected], frame.question


@pytest.mark.parametrize(
    ("which", "who", "text", "expected"),
    [
        # must not change: an owner with no such thing is not given another's; the office's
        # own words are read as they are
        ("harbour", "pat", "can I borrow Mark's lamp", []),
        (
            "harbour",
            "will",
            "take my inspection lamp to Rose",
            [("inspection_lamp", "will", "rose")],
        ),
        ("harbour", "pat", "can I borrow Grace's highlighter", [("highlighter", "grace", "pat")]),
        ("default", "zhang", "bring me Lee's book", [("book", "lee", "zhang")]),
    ],
)
def test_neighbours_keep_their_reading(
    which: str, who: str, text: str, expected: list[tuple[str, str | None, str]]
) -> None:
    frame = _read(which, text, who)
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == expected, frame.question
