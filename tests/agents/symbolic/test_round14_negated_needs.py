"""A need said negated after its subject ("Teodor doesn't need a glue stick", "my contract
does not need a vet") is told, never a command after an aside: found while reading an
operation named by a noun (``reading.operation_nouns``), on the radio station office."""

from __future__ import annotations

import functools

import pytest

from helpers.radio_station import radio_station
from helpers.reading import parser_for

_parser = functools.partial(parser_for, radio_station)


@pytest.mark.parametrize(
    ("text", "who"),
    [
        ("Teodor doesn't need a glue stick", "basil"),
        ("my poster doesn't need a glue stick", "wren"),
        ("my contract does not need a vet", "basil"),
        ("Linnea never needs a marker pen", "wren"),
    ],
)
def test_a_negated_need_moves_nothing(text: str, who: str) -> None:
    frame = _parser().parse(text, who)
    assert not frame.tasks, (text, frame)


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("I have faith in you bring me a glue stick", "glue_stick"),
        ("don't need a glue stick, bring me a marker pen", "marker_pen"),
    ],
)
def test_a_command_after_an_aside_still_asks(text: str, item: str) -> None:
    assert [t.item for t in _parser().parse(text, "wren").tasks] == [item]
