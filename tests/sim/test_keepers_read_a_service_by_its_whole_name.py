"""A colleague reads a service the robot asks for by its whole name ("could anyone print
barcode labels ...") as that one service, even where the name's first word is the printer's
verb and also a name of the printout ("a print"), and a later word is the service's own verb
("barcode"). Read before, "print" was kept as the printer's verb and "barcode" dropped as
that verb's noun, so keepers of the plain printer volunteered and the label run's keepers
never saw their own service asked for (a prop hire office's barcode labels)."""

from __future__ import annotations

from typing import Any

import pytest

from assistantx.core.office import Office, parse_office
from assistantx.sim.understanding import mentioned_requests
from helpers.archive import raw_archive


def _barcode_office() -> Office:
    raw: dict[str, Any] = raw_archive()
    for item in raw["item_types"]:
        if item["id"] == "printout":
            item["synonyms"] = ["print", "hard copy"]
        if item["id"] == "box_label":
            item.update(name="barcode labels", synonyms=["barcodes", "labels"])
    for op in raw["operations"]:
        if op["id"] == "tag":
            op.update(name="print barcode labels", verbs=["tag", "barcode", "label"])
    return parse_office(raw)


@pytest.mark.parametrize(
    "text",
    [
        "could anyone print barcode labels the document file at the tag printer?",
        "Could anyone in the group print barcode labels for Ines's document file?",
        "I could not print barcode labels your file",
    ],
)
def test_the_whole_name_asks_for_that_one_service(text: str) -> None:
    assert mentioned_requests(_barcode_office(), text) == ["tag"]


@pytest.mark.parametrize(
    ("text", "asked"),
    [
        # near-misses: the printer's own work, and both said apart, are read as before
        ("could you print my box list?", ["print"]),
        ("could you print my box list and barcode it?", ["print", "tag"]),
        ("could you print and label my document?", ["print", "tag"]),
        ("could you tag my document?", ["tag"]),
    ],
)
def test_the_words_said_apart_keep_their_own_services(text: str, asked: list[str]) -> None:
    assert mentioned_requests(_barcode_office(), text) == asked
