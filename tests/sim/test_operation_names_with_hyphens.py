"""A keeper with two services at one desk runs the one their code's message names, also when
the service's name is written with a hyphen ("date-stamp", "off-site archive"): the message's
words are split at the hyphen, so the name must be too. It had read "date-stamp it" as no
name at all and run the desk's first service, a courier, so the document left the office and
the requester found the locker empty (the dataset generator's optimal run failed on such an
office)."""

from __future__ import annotations

import pytest

from assistantx.core.office import parse_office
from assistantx.sim.people import perform_handover
from assistantx.sim.world import LOCKER, World
from helpers import office_builder as ob
from helpers.notary_office import raw_notary_office


def _post_desk_with(name: str) -> World:
    raw = raw_notary_office()
    raw["operations"].append(
        ob.operation("stamp_in", "date-stamp", name=name, input="document", done="stamped")
    )
    desk = next(f for f in raw["facilities"] if f["id"] == "courier_desk")
    desk["operations"] = ["courier", "stamp_in"]  # the courier first: the old fallback
    world = World.from_office(parse_office(raw))
    world.move_item(0.0, "document:ruth", LOCKER, by="ruth")
    return world


@pytest.mark.parametrize("name", ["date-stamp", "date stamp", "receipt date-stamp"])
def test_the_named_service_runs_and_the_document_comes_back(name: str) -> None:
    world = _post_desk_with(name)
    told = f"take Ruth Okafor's document out, {name} it and put it back"
    perform_handover(world, 1.0, "tomasz", "heat", "document:ruth", "post_room", told)
    assert world.holder["document:ruth"] == LOCKER
    assert world.sent_out() == []


def test_a_message_naming_the_courier_still_sends_it_out() -> None:
    world = _post_desk_with("date-stamp")
    told = "take Ruth Okafor's document out, courier it to Leeds Records and put it back"
    perform_handover(world, 1.0, "tomasz", "heat", "document:ruth", "post_room", told)
    assert [e.kind for e in world.sent_out()] == ["sent_out"]
