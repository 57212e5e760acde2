""" "this", "that" or "it" carried somewhere with nothing said that it could be is asked
about, never guessed from where it goes: "can you take this over to the tyre store" (a
store that calibrates gauges) calibrated someone's gauge; here "take this to the scanner"
scanned the requester's document, "take that to the franking machine" made a stamped
envelope and "can you take it to the coffee machine" a coffee. A message that names the
thing ("print my report and take it to Wang") keeps its reading."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "lin")
_harbour = frame_reader(harbour_office, "will")


@pytest.mark.parametrize(
    ("text", "said"),
    [
        ("can you take this over to the printer", "'this'"),
        ("can you take it to the coffee machine", "'it'"),
        ("could you drop these over to the vending machine", "'these'"),
    ],
)
def test_an_unnamed_thing_carried_is_asked_about(text: str, said: str) -> None:
    frame = _default(text)
    assert frame.tasks == []
    assert frame.question is not None and said in frame.question


def test_to_a_colleague_it_is_asked_too() -> None:
    """ "take that to Wang": nothing moves; the reader asks (what to do, with which item)."""
    frame = _default("take that to Wang")
    assert frame.tasks == [] and frame.question is not None


@pytest.mark.parametrize(
    "text", ["take this to the scanner", "take that to the franking machine please"]
)
def test_the_same_on_harbour(text: str) -> None:
    frame = _harbour(text)
    assert frame.tasks == []
    assert frame.question is not None and "what is" in frame.question


@pytest.mark.parametrize(
    ("text", "tasks"),
    [
        ("print my report and take it to Wang", [("print", "file", "wang")]),
        ("my stapler is on my desk, take it to Wang", [("transfer", "stapler", "wang")]),
        ("take my stapler to Wang", [("transfer", "stapler", "wang")]),
    ],
)
def test_a_thing_named_keeps_its_reading(text: str, tasks: list[tuple[str, str, str]]) -> None:
    """Neighbours: "it" has an antecedent, or the thing is named."""
    frame = _default(text)
    assert frame.question is None, frame.question
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == tasks
