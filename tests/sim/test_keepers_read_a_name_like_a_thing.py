"""A colleague's full name in the robot's question is a name, never a thing of the office
(blind round 27's class, on ``helpers.orchestra_pit``): asked to take "Viola Hart's lunch"
out of the fridge where a viola is an instrument, the fridge's keeper takes out the lunch; on
main she answered "Sorry, I don't have Viola Hart's instrument" and the lunch never came."""

from __future__ import annotations

from assistantx.agents.symbolic.answers import stance
from assistantx.sim.people import direct_reply
from assistantx.sim.understanding import mentioned_item_types
from assistantx.sim.world import World
from helpers.orchestra_pit import orchestra_pit

_ASKED = "Hi Maud, could you take Viola Hart's lunch out of the band-room fridge for the robot?"


def test_the_thing_asked_for_is_read_past_the_name() -> None:
    assert mentioned_item_types(orchestra_pit(), _ASKED) == ["lunch"]


def test_the_keeper_says_yes_to_the_lunch() -> None:
    reply = direct_reply(World.from_office(orchestra_pit()), "maud", _ASKED)
    assert reply is not None and stance(reply.text) == "yes", reply


def test_the_instrument_named_as_a_thing_is_still_read() -> None:
    asked = "Hi Maud, could you take Ines Varga's viola out of the practice room for the robot?"
    assert mentioned_item_types(orchestra_pit(), asked) == ["cello"]
