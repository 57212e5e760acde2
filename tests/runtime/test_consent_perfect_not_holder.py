"""The consent guard's pronoun recipient: one said to have *done* something ("Mei has hurt her
ankle") is no holder of a thing. "has" before a past participle is the perfect of the verb,
a thing that happened to her, not a having, so "take her an ice pack" means her; one said to
have a thing ("Rui has a spare one") still holds it and is never "her"."""

from __future__ import annotations

from typing import Any

import pytest

from assistantx.core.actions import SendQR
from assistantx.runtime import consent
from assistantx.runtime.recipients import named_recipients
from helpers import office_builder as ob
from helpers.consent_memory import answered, memory


def _raw_club() -> dict[str, Any]:
    """A club: a first-aid cabinet (a facility, owned by nobody, Kit keeps its key) in
    the office keeps ice packs; the pool hall is a plain room."""
    return ob.office_file(
        "club",
        (
            ob.person("mei", "Mei Tan", "towel"),
            ob.person("rui", "Rui Costa", "towel"),
            ob.person("ola", "Ola Berg", "towel"),
            ob.person("kit", "Kit Marsh", at="office"),
        ),
        rooms=[
            ob.room("pool_hall", "Pool hall", 4.0, 20.5, kind="room"),
            ob.room("office", "Club office", 14.0, 20.5),
        ],
        item_types=[
            ob.item("ice_pack", "ice pack", synonyms=["cold pack"]),
            ob.item("towel", "towel"),
        ],
        operations=[],
        facilities=[
            ob.facility(
                "first_aid",
                "first-aid cabinet",
                at="office",
                guards=["kit"],
                supplies=["ice_pack"],
            )
        ],
        home="office",
    )


club = ob.parsed(_raw_club)


@pytest.mark.parametrize(
    "text",
    [
        "Mei has hurt her ankle in the pool hall. Can you take her an ice pack?",
        "Mei has twisted her knee, bring her an ice pack please",
        "Mei has cut her hand, take her my towel",
        # what she has is no thing of the office: what she is busy with, not a having
        "Mei has a swimming lesson soon. Can you take her an ice pack?",
        "Mei has a flat tyre in the car park, take her my towel",
    ],
)
def test_one_said_to_have_done_something_is_whom_her_means(text: str) -> None:
    office = club()
    stm = memory("ola", text)
    assert named_recipients(office, stm) == {"mei"}, text
    answered(stm, "mei", "rui")
    code = SendQR(contact="mei", item="ice_pack", purpose="collect")
    assert consent.check(office, stm, code) is None
    other = consent.check(office, stm, SendQR(contact="rui", item="ice_pack", purpose="collect"))
    assert other is not None and other.rule == "not_a_party"


@pytest.mark.parametrize(
    "text",
    [
        # the one said to have the thing is where it comes from, never "her"
        "Mei has hurt her ankle. Rui has a spare towel, take it to her",
        "Mei has hurt her ankle. Rui has got a towel, bring it to her",
        "Mei has hurt her ankle. Rui has a spare one, take it to her",
        "Mei has hurt her ankle. Rui has a cold pack, bring it to her",
    ],
)
def test_one_said_to_have_a_thing_is_still_its_holder(text: str) -> None:
    assert named_recipients(club(), memory("ola", text)) == {"mei"}, text
