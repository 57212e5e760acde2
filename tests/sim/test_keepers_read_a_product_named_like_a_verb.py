"""A simulated keeper reads "could you print labels ..." as the label run where the plain
printer's printout is also called "a print": "labels" is the label run's product, not a form
of its verb "label" whose means was the printer's "print" (blind round 22: the label
printer's keeper answered "I can't help with that (print)" and three tasks failed)."""

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
            item["synonyms"] = [*item.get("synonyms", []), "print"]
    return parse_office(raw, "kitchen with prints")


@pytest.mark.parametrize(
    ("text", "requests"),
    [
        ("Hi Ines, could you print labels Odile's recipe file at the label printer?", ["label"]),
        ("could anyone print labels for Odile?", ["label"]),
        ("could you label Odile's file?", ["label"]),
        ("could you print Odile's file?", ["print"]),
        ("could you do me a print of Odile's file?", ["print"]),
    ],
)
def test_the_product_says_which_run(text: str, requests: list[str]) -> None:
    assert [r for r in mentioned_requests(_office(), text) if r != "send_file"] == requests
