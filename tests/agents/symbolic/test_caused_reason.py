"""Fixer fix180c class 1: "can u get my swab tested, the reading looked off on my kit". The
causative "get <my thing> <participle>" asks the participle's work on that thing: a thing the
office has no word for is guessed from that work as it is after the verb ("test my swab",
``own_papers``), and a reason told after the participle without a stop is a clause of its own
(``caused_reason``): a thing named in it ("my kit", another item's name) is no thing of the
request. Before, the swab was unread and the kit asked about."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.caused_reason import caused_then_told
from helpers.reading import answered_reader, frame_reader
from helpers.swab_clinic import swab_clinic

_read = frame_reader(swab_clinic, "ines")
_answered = answered_reader(swab_clinic, "ines")


@pytest.mark.parametrize(
    "text",
    [
        "can u get my swab tested, the reading looked off on my kit",
        "can u get my swab tested the reading looked off on my kit",
        "get my swab tested please",
        "could you have my swab tested? my kit gave a weird reading",
    ],
)
def test_the_causatives_work_is_done_on_the_guessed_thing(text: str) -> None:
    frame = _read(text)
    # "Shall I test your test sample for you?": the guess restated, never the kit asked
    assert frame.question is not None and "test your test sample" in frame.question, frame
    frame = _answered(text, ["yes"])
    tasks = [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]
    assert tasks == [("copy", "sample", "ines", "ines")], frame


@pytest.mark.parametrize(
    "text",
    [
        # neighbours: the work said before the thing; the office's own name of the thing
        "can u test my swab",
        "can u get my sample tested the reading looked off on my kit",
    ],
)
def test_neighbours_read_the_sample(text: str) -> None:
    said = _read(text).question or ""
    frame = _answered(text, ["yes"])
    tasks = [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]
    assert tasks == [("copy", "sample", "ines", "ines")], frame
    assert "kit" not in said, frame


@pytest.mark.parametrize(
    ("text", "said"),
    [
        (
            "get my swab tested the reading looked off on my kit",
            "get my swab tested, the reading looked off on my kit",
        ),
        (
            "can you have the form signed my manager is away",
            "can you have the form signed, my manager is away",
        ),
        # must not change: no subject and verb after the participle, or a stop already
        ("get my file printed the same way", "get my file printed the same way"),
        ("have the form signed the day it is due", "have the form signed the day it is due"),
        (
            "get my swab tested. the reading looked off",
            "get my swab tested. the reading looked off",
        ),
        ("I got my swab tested the reading was low", "I got my swab tested, the reading was low"),
    ],
)
def test_a_reason_after_the_participle_is_a_clause_of_its_own(text: str, said: str) -> None:
    assert caused_then_told(text) == said
