"""A colleague's place said as where a thing comes from: "we're out of glue at the bench, could
you get a tube from Priya's cabinet" (fixer fix189c; the round's own offices and sentences were
never read). The office's glue is a supply nobody owns, kept at the parts cabinet that Priya
looks after; "from Priya's cabinet" names where it is kept, and was read as Priya's own glue,
which she has not. The office is built here: Priya and Kai keep the cabinet, Kai and Tom have
tape of their own."""

from __future__ import annotations

from typing import Any

import pytest

from assistantx.agents.symbolic.reading.parser import InstructionParser
from helpers import office_builder as ob


def _raw(synonyms: tuple[str, ...]) -> dict[str, Any]:
    people = (
        ob.person("priya", "Priya Nair", "mug"),
        ob.person("kai", "Kai Long", "mug", "tape"),
        ob.person("tom", "Tom Reed", "mug", "tape"),
        ob.person("ana", "Ana Silva", "mug"),
    )
    return ob.office_file(
        "workshop",
        people,
        rooms=[
            ob.room("stores", "Parts room", 4.0, 20.0),
            ob.room("bench", "Work bench", 12.0, 20.0),
        ],
        item_types=[
            ob.item("glue", "glue", consumable=True, mass=True),
            ob.item("thread", "thread", consumable=True, mass=True),
            ob.item("tape", "tape", consumable=True),
            ob.item("mug", "mug"),
        ],
        operations=[],
        facilities=[
            ob.facility(
                "cabinet",
                "parts cabinet",
                at="stores",
                guards=["priya", "kai"],
                supplies=("glue", "tape"),
                synonyms=synonyms,
            )
        ],
        home="stores",
    )


_PARSERS = {
    "cabinet said": InstructionParser(ob.parsed(lambda: _raw(("cabinet",)))()),
    "cabinet unsaid": InstructionParser(ob.parsed(lambda: _raw(()))()),
}


def _tasks(text: str, office: str = "cabinet said") -> list[tuple[str, str | None, str | None]]:
    frame = _PARSERS[office].parse(text, "ana")
    return [(t.kind, t.item, t.owner) for t in frame.tasks]


def _question(text: str) -> str | None:
    return _PARSERS["cabinet said"].parse(text, "ana").question


@pytest.mark.parametrize("office", ["cabinet said", "cabinet unsaid"])
@pytest.mark.parametrize(
    "text",
    [
        "we're out of glue at the bench, could you get a tube from Priya's cabinet",
        "could you get a tube of glue from Priya's cabinet",
        "get me some glue from Priya's cupboard",
        "grab me some glue out of Priya's drawer",
    ],
)
def test_the_supply_kept_where_the_colleague_looks_after_it(text: str, office: str) -> None:
    assert _tasks(text, office) == [("transfer", "glue", None)]


def test_a_colleague_with_their_own_and_the_kept_one_is_asked_which() -> None:
    asked = _question("get me a roll of tape from Kai's cabinet")
    assert asked is not None and "Kai Long's own" in asked and "parts cabinet" in asked


def test_a_colleague_with_none_who_keeps_none_is_asked_where() -> None:
    # Tom keeps nothing and has no glue: never a fetch of glue of his
    asked = _question("get me some glue from Tom's drawer")
    assert asked is not None and "Tom Reed has no glue" in asked


# -- must not change --------------------------------------------------------------------------
def test_a_colleague_with_their_own_and_no_kept_one_gives_their_own() -> None:
    assert _tasks("get me a roll of tape from Tom's drawer") == [("transfer", "tape", "tom")]


def test_the_colleagues_own_thing_said_so_is_theirs() -> None:
    assert _tasks("get me Kai's tape") == [("transfer", "tape", "kai")]


def test_the_requesters_own_thing_at_a_colleagues_place_is_theirs() -> None:
    assert _tasks("take my mug from Priya's desk") == [("transfer", "mug", "ana")]


def test_the_facility_said_without_its_keeper_is_as_before() -> None:
    assert _tasks("get me glue from the parts cabinet") == [("transfer", "glue", None)]


def test_my_facility_is_still_asked() -> None:
    asked = _question("get me glue from my cabinet")
    assert asked is not None and "my cabinet" in asked
