"""A simulated colleague reads "could you spare Sam some of your lube?" as a request to lend,
where "spare" is also a name of the key cutter's product (a spare key): a product's one-word
name said in the verb's place, right after "you", "anyone" or "please", is the verb. Blind
round 205: every owner of the lube answered "Sorry, I can't help with that (cut)" to the
robot's question, and eleven tasks failed."""

from __future__ import annotations

from typing import Any

import pytest

from assistantx.core.office import Office, parse_office
from assistantx.sim.understanding import mentioned_requests
from helpers.airside_kitchen import raw_airside_kitchen


def _office() -> Office:
    raw: dict[str, Any] = raw_airside_kitchen()
    for item in raw["item_types"]:
        if item["id"] == "printout":
            item["synonyms"] = [*item.get("synonyms", []), "spare"]
    return parse_office(raw, "kitchen with spares")


@pytest.mark.parametrize(
    ("text", "requests"),
    [
        ("Hi Ines, could you spare Odile some of your trimmings?", []),
        ("please spare me a minute", []),
        # the group's question, asked of anyone (round 205 at L3: "I can help with that (cut)")
        ("Hi all, could anyone spare Odile some trimmings? Please reply here if you can", []),
        # the product asked for as a thing stays the run that makes it
        ("could you do me a spare of Odile's file?", ["print"]),
        ("a spare of Odile's file please", ["print"]),
        ("could you spare me a spare of Odile's file?", ["print"]),
        ("could you print Odile's file?", ["print"]),
    ],
)
def test_a_product_name_in_the_verb_place_is_the_verb(text: str, requests: list[str]) -> None:
    assert [r for r in mentioned_requests(_office(), text) if r != "send_file"] == requests
