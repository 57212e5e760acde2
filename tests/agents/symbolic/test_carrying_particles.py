"""The particle of a carrying verb is part of the verb (fix93e class 3): "could you bring some
*up* to reception" after "Any tea left in the kitchen?" was declined as "there is no up to
reception". After a stand-in for a thing named elsewhere ("some", "a couple", "one") and before
"to", the particle is dropped and "to" opens the destination. "it's up to you" and a named
item ("bring a ruler up to reception") read as before."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.carrying_particles import carrying_particles
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_harbour = frame_reader(harbour_office, "rose")
_default = frame_reader(default_office, "lee")


@pytest.mark.parametrize(
    "text",
    [
        "Any tea left in the kitchen? could you bring some up to reception",
        "is there any tea? fetch a couple up to reception",
        "any tea going? could you send some round to reception",
        "Any tea left in the kitchen? could you bring some to reception",
        # the particle ends the clause, no destination said (blind round 93, after the fix)
        "is there any tea in the kitchen? could you bring some up, ours has gone off",
        "any tea going? send a couple over.",
    ],
)
def test_the_stand_in_is_the_thing_asked_about_in_harbour(text: str) -> None:
    frame = _harbour(text)
    assert frame.decline is None and frame.question is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("produce", "tea", "rose")]


def test_the_destination_after_the_particle_is_a_colleague_in_the_default_office() -> None:
    frame = _default("is there coffee? could you bring some up to Wang")
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("produce", "coffee", "wang")]


def test_a_named_pen_sent_up_to_the_speakers_desk() -> None:
    frame = _default("I'm out of pens, could you send some up to my desk")
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", "pen", "lee")]


@pytest.mark.parametrize(
    ("text", "kept"),
    [
        ("it's up to you which ruler", True),  # after a "to be": a choice left to you
        ("print some up to 5 pages", True),  # a limit, a number after "to"
        ("bring a ruler up to reception", True),  # a named item: read as before
        ("run it over to them", True),  # the errand's own particle after "it"
        ("send one down to the lab", False),
        ("send a couple round to Mark", False),
        ("could you bring some up, ours has gone off", False),
        ("pick it up, please", True),  # a pronoun's particle makes another verb
        ("some up front costs", True),  # no clause's end after it
    ],
)
def test_only_a_stand_in_before_to_loses_its_particle(text: str, kept: bool) -> None:
    assert (carrying_particles(text) == text) is kept


def test_up_to_you_moves_nothing() -> None:
    assert _harbour("it's up to you which ruler").tasks == []
