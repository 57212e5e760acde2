"""A declared verb phrase that is also the name of a thing of the office ("bubble-wrap", a
packing service's verb, beside the bubble wrap the packing store keeps for anyone): after a
determiner, a quantity or a receiver it is the thing ("some bubble wrap", "bring me bubble
wrap"); in a verb's place it is still the work ("can you bubble-wrap my lot")."""

from __future__ import annotations

from typing import Any

import pytest

from assistantx.agents.symbolic import InstructionParser
from helpers import office_builder as ob


def _raw_saleroom() -> dict[str, Any]:
    people = (
        ob.person("amber", "Amber Kay", "lot"),
        ob.person("otto", "Otto Lind"),
    )
    return ob.office_file(
        "saleroom",
        people,
        rooms=[ob.room("packing_store", "Packing store", 20.0, 20.0)],
        item_types=[
            ob.item("lot", "lot", "personal"),
            ob.item("bubble_wrap", "bubble wrap", synonyms=["bubblewrap"], mass=True),
            ob.item("tape", "tape"),
        ],
        operations=[
            ob.operation(
                "pack", "pack", "box up", "bubble-wrap", name="pack for collection", input="lot"
            ),
        ],
        facilities=[
            ob.facility(
                "packing_store",
                "packing store",
                at="packing_store",
                guards=["otto"],
                operations=["pack"],
                supplies=["bubble_wrap", "tape"],
            ),
        ],
        home="packing_store",
    )


_saleroom = ob.parsed(_raw_saleroom)


def _tasks(text: str) -> list[tuple[str, str | None, str | None]]:
    frame = InstructionParser(_saleroom()).parse(text, "amber")
    assert frame.question is None and frame.decline is None, frame
    return [(t.kind, t.item, t.operation) for t in frame.tasks]


@pytest.mark.parametrize(
    "text",
    [
        "Bring me some bubble wrap from the packing store, please.",
        "could I get some more bubble wrap",
        "bring me bubble wrap pls",
        "grab me the bubble wrap from the store",
    ],
)
def test_the_things_name_after_a_determiner_quantity_or_receiver_is_the_thing(text: str) -> None:
    assert [(kind, item) for kind, item, _ in _tasks(text)] == [("transfer", "bubble_wrap")]


@pytest.mark.parametrize("text", ["can you bubble-wrap my lot", "please bubble wrap my lot"])
def test_the_phrase_in_a_verbs_place_is_still_the_work(text: str) -> None:
    # the office's one service of that shape on the lot (its id is left to the planner)
    assert [(kind, item) for kind, item, _ in _tasks(text)] == [("heat", "lot")]
