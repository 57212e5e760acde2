"""The words that open a verb's object are one list (``object_starts`` in
``data/english.yaml``), read by every rule that looks for an object after a verb: a contracted
"has" before its object ("the printer's eaten *those* forms"), a purpose's own object ("something
to cut *a* ribbon with"), and a clause opening with a past verb ("Spilled *this* coffee ...").
Each rule once kept a list of its own, and each list missed words the others had."""

from __future__ import annotations

import pytest

from assistantx.core.office import load_office
from helpers.port_office import port_office
from helpers.reading import frame_reader

_default = frame_reader(load_office, "lee")
_port = frame_reader(port_office, "tom")


@pytest.mark.parametrize(
    "text",
    [
        "ugh the printer's eaten those forms",
        "the shredder's chewed these pages",
        "the printer's eaten your report",
    ],
)
def test_a_contracted_has_before_any_object_is_a_statement(text: str) -> None:
    frame = _default(text)
    assert frame.tasks == [] and frame.question is None, frame


@pytest.mark.parametrize(
    "text",
    [
        "can you find something to cut a ribbon with",
        "something to cut these with",
        "anything I can cut this ribbon with?",
    ],
)
def test_a_purpose_with_its_own_object_names_the_tool(text: str) -> None:
    frame = _default(text)
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("scissors", None, "lee")]


@pytest.mark.parametrize(
    "text",
    [
        "Left your radio at home, sorry",
        "Spilled this coffee all over the desk",
        "Dropped those radios in the harbour",
    ],
)
def test_a_clause_opening_with_a_past_verb_and_any_object_is_told(text: str) -> None:
    frame = _port(text)
    assert frame.tasks == [] and frame.question is None, frame


def test_the_plain_verb_with_the_same_object_is_still_asked() -> None:
    frame = _port("bring those radios to Drew")
    assert [(t.item, t.recipient) for t in frame.tasks] == [("radio", "drew")], frame
