"""A colleague's full name in the robot's question is a name, never a thing of the office
(blind round 27's class, on ``helpers.orchestra_pit``): asked to take "Viola Hart's lunch"
out of the fridge where a viola is an instrument, the fridge's keeper takes out the lunch; on
main she answered "Sorry, I don't have Viola Hart's instrument" and the lunch never came."""

from __future__ import annotations

from assistantx.agents.symbolic.answers import stance
from assistantx.core.office import Office
from assistantx.sim.people import direct_reply
from assistantx.sim.understanding import mentioned_item_types, mentioned_requests
from assistantx.sim.world import World
from helpers import office_builder as ob
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


def _post_room() -> Office:
    """A post room whose franking machine is asked for with "frank", beside a Frank."""
    return ob.parsed(
        lambda: ob.office_file(
            "post room",
            (ob.person("frank", "Frank Szabo"), ob.person("jo", "Jo Park", "tape_gun")),
            rooms=[ob.room("post_room", "Post room", 4.0, 20.0)],
            item_types=[
                ob.item("tape_gun", "tape gun"),
                ob.item("parcel", "parcel", "personal"),
            ],
            operations=[ob.operation("frank", "frank", input="parcel")],
            facilities=[
                ob.facility(
                    "franker",
                    "franking machine",
                    at="post_room",
                    guards=["jo"],
                    operations=["frank"],
                )
            ],
            home="post_room",
        )
    )()


def test_a_name_that_is_a_services_verb_asks_for_no_service() -> None:
    """Blind round 29's refused base: asked to lend "Frank Szabo" a tape gun, the owner read
    a franking request in the name and never lent it (the generator refused the task)."""
    asked = "Hi Jo, could you lend Frank Szabo your tape gun?"
    office = _post_room()
    assert mentioned_requests(office, asked) == []
    reply = direct_reply(World.from_office(office), "jo", asked)
    assert reply is not None and stance(reply.text) == "yes", reply
