"""A product made by a phrasal verb, asked of "someone" (blind round 17's class, on a school
office no sentence was written for, ``helpers.playschool``, whose props bench makes "stage
blood", also called "fake blood"): "can someone/somebody/anyone V", "could one of you V" ask
for V, never decline "someone mix" as a service the office lacks; "mix up", "make up",
"knock up", "rustle up", "run off" make the product. The office's operation may have its own
verb or none."""

from __future__ import annotations

import functools

import pytest

from assistantx.agents.symbolic import InstructionParser
from helpers import office_builder as ob
from helpers.playschool import playschool, raw_playschool
from helpers.reading import frame_reader

_frame = frame_reader(playschool, "ada")


@functools.cache
def _verbless() -> InstructionParser:
    """The props bench's operation with no verb of its own, named "make stage blood"."""
    raw = raw_playschool()
    for op in raw["operations"]:
        if op["id"] == "mix":
            del op["verbs"]
            op["name"] = "make stage blood"
    return InstructionParser(ob.parsed(lambda: raw)())


_BLOOD_ASKED = [
    "need more fake blood for tonight, can someone mix some up for me",
    "can someone mix up some fake blood",
    "could one of you mix up some stage blood for me",
    "can anybody knock up some fake blood please",
    "can somebody rustle up more stage blood for the dress rehearsal",
    "we're out of fake blood, could someone make some up",
]


@pytest.mark.parametrize("text", _BLOOD_ASKED)
def test_someone_asked_to_make_the_product_makes_it(text: str) -> None:
    for frame in (_frame(text), _verbless().parse(text, "ada")):
        assert frame.question is None and frame.decline is None, frame
        assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
            ("produce", "stage_blood", "ada")
        ]


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("can someone rustle up a practical kit for me", "practical_kit"),
        ("could one of you make up a practical kit", "practical_kit"),
        ("can anyone run off a script pack for me", "script"),
    ],
)
def test_other_products_by_phrasal_verbs(text: str, item: str) -> None:
    frame = _frame(text)
    assert frame.question is None and frame.decline is None, frame
    assert [t.item for t in frame.tasks] == [item]


@pytest.mark.parametrize(
    "text",
    [
        "can someone bring me Rory's stapler",
        "could one of you bring me Rory's stapler",
        "can anybody grab me Rory's stapler",
    ],
)
def test_someone_asked_to_fetch_fetches(text: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "stapler", "rory", "ada")
    ]


@pytest.mark.parametrize(
    "text",
    [
        "did someone mix up the fake blood already?",
        "someone mixed up some fake blood yesterday, thanks",
        "no need for anyone to mix up fake blood",
    ],
)
def test_near_misses_move_nothing(text: str) -> None:
    assert _frame(text).tasks == []
