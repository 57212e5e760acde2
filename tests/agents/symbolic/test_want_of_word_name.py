"""Issue #23, fixer fix151c class 4: a colleague's want said with a helping verb ("could do
with", "could use", "would like") of a name that is also an English word, typed in lower case
("frank could do with a radio, his died on him", "mark could do with a ruler"), is that
colleague's need, confirmed with the requester before anyone's thing moves ("Shall I bring a
walkie-talkie to Frank Odell?"), as "Frank could do with a radio" already was
(``named_want``: the name is read in a subject's place). Before, "frank" alone read as the
English word, the want was left as request wording, and Chase's walkie-talkie was lent to
Frank without a word to the requester; "frank would like a radio" even fetched one for the
requester."""

from __future__ import annotations

from typing import Any

import pytest
from symbolic_run import run_instruction

from assistantx.core.office import load_office
from helpers.atelier import atelier
from helpers.dataset_offices import harbour_office
from helpers.reading import answered_reader

_default = answered_reader(load_office, "lee")
_harbour = answered_reader(harbour_office, "rose")
_atelier = answered_reader(atelier, "mara")


@pytest.mark.parametrize(
    ("read", "text", "asked", "item", "needer"),
    [
        (
            _atelier,
            "frank could do with a radio, his died on him",
            "Shall I bring a walkie-talkie to Frank Odell?",
            "walkie",
            "frank",
        ),
        (
            _atelier,
            "frank could use a radio",
            "Shall I bring a walkie-talkie to Frank Odell?",
            "walkie",
            "frank",
        ),
        (
            _atelier,
            "frank would like a radio",
            "Shall I bring a walkie-talkie to Frank Odell?",
            "walkie",
            "frank",
        ),
        (
            _harbour,
            "mark could do with a ruler",
            "Shall I bring a ruler to Mark Lindqvist?",
            "ruler",
            "mark",
        ),
        (
            _harbour,
            "will could do with a ruler, his snapped",
            "Shall I bring a ruler to Will Tanaka?",
            "ruler",
            "will",
        ),
        (
            _default,
            "fang could do with a stapler",
            "Shall I bring a stapler to Wang Fang?",
            "stapler",
            "wang",
        ),
    ],
)
def test_confirmed_first_then_brought_on_yes(
    read: Any, text: str, asked: str, item: str, needer: str
) -> None:
    frame = read(text)
    assert frame.tasks == [] and frame.question == asked, frame
    yes = read(text, ("yes",))
    assert [(t.kind, t.item, t.recipient) for t in yes.tasks] == [("transfer", item, needer)], yes
    no = read(text, ("no thanks",))
    assert no.tasks == [], no


@pytest.mark.parametrize(
    ("read", "text", "recipient"),
    [
        # neighbours: the requester's own want, and a request that asks for the delivery
        (_default, "I could do with a stapler", "lee"),
        (_atelier, "can you get frank a radio", "frank"),
        (_atelier, "Frank needs a radio, can you sort one", "frank"),
    ],
)
def test_asked_deliveries_are_read_as_before(read: Any, text: str, recipient: str) -> None:
    frame = read(text)
    assert [(t.kind, t.recipient) for t in frame.tasks] == [("transfer", recipient)], frame


async def test_end_to_end_nothing_moves_before_the_requester_says_yes() -> None:
    run = await run_instruction(atelier(), "mara", "frank could do with a radio, his died on him")
    assert run.actions[0] == "inquire", run.actions
    assert run.sim.world.handovers() == [], run.stm.trace.summary
