"""A simulated keeper understands a request for the office's own operation by its declared
phrase, its name or its product's name, as a colleague who works there would (workshops of
``helpers.fablab``, written for these tests): "3D print" is the 3D printer's work, not the
plotter's "print" inside it; "make up a kit bag" asks for the kit bag to be made, even where a
shorter thing's name ("kit", a first aid kit) stands inside the product's name."""

from __future__ import annotations

import pytest

from assistantx.sim.people import direct_reply, group_replies
from assistantx.sim.understanding import mentioned_requests
from assistantx.sim.world import World
from helpers.fablab import costume_works, fablab


@pytest.mark.parametrize(
    ("text", "requests"),
    [
        ("Hi Priit, could you 3D print Ines Varga's design file at the 3D printer?", ["print3d"]),
        ("could anyone 3d-print my file?", ["print3d"]),
        ("Hi Priit, could you laser cut Ines Varga's design file at the laser cutter?", ["cut"]),
        ("Hi Hana, could you plot Ines Varga's design file at the plotter?", ["plot"]),
        ("could you print my file?", ["plot"]),
        (
            "Hi Wanda, could you make up a kit bag for Ines Varga at the stores cupboard?",
            ["bundle"],
        ),
        ("Hi Wanda, could you get kit bag for Ines Varga from the stores cupboard?", ["bundle"]),
        ("Hi Wanda, could you lend Ines Varga your first aid kit?", []),
    ],
)
def test_the_longest_phrase_says_the_operation(text: str, requests: list[str]) -> None:
    assert [r for r in mentioned_requests(fablab(), text) if r != "send_file"] == requests


@pytest.mark.parametrize(
    ("text", "requests"),
    [
        ("Hi Fitz, could you heat press Ada Quist's artwork at the heat press?", ["heatpress"]),
        ("Hi Esme, could you press Ada Quist's costume in the wardrobe?", ["steam"]),
        ("Hi Dov, could you vinyl cut Ada Quist's artwork at the vinyl cutter?", ["vinyl"]),
        ("Hi Dov, could you laser engrave Ada Quist's artwork?", ["engrave"]),
    ],
)
def test_the_costume_works_phrases_are_read_whole(text: str, requests: list[str]) -> None:
    assert [r for r in mentioned_requests(costume_works(), text) if r != "send_file"] == requests


def test_the_3d_printers_keeper_agrees_and_the_plotters_does_not_volunteer() -> None:
    world = World.from_office(fablab())
    asked = "Hi Priit, could you 3D print Ines Varga's design file at the 3D printer?"
    reply = direct_reply(world, "priit", asked)
    assert reply is not None and reply.text.startswith("Yes, I can do that (print3d)")
    group = "Hi all, could anyone 3D print Ines Varga's design file at the 3D printer?"
    everyone = [p.id for p in fablab().people]
    assert [r.person for r in group_replies(world, everyone, group)] == ["priit"]


def test_the_stores_keeper_agrees_to_make_up_a_kit_bag() -> None:
    world = World.from_office(fablab())
    asked = "Hi Wanda, could you make up a kit bag for Ines Varga at the stores cupboard?"
    reply = direct_reply(world, "wanda", asked)
    assert reply is not None and reply.text.startswith("Yes, I can do that (bundle)")
    # her own first aid kit, asked for as a thing, is still a thing she lends
    lend = direct_reply(world, "wanda", "Hi Wanda, could you lend Ines Varga your first aid kit?")
    assert lend is not None and "first aid kit" in lend.text


def test_a_request_naming_only_the_machine_asks_for_its_operation() -> None:
    world = World.from_office(fablab())
    asked = "Hi Priit, could you run Ines Varga's design file through the 3D printer?"
    keeper = direct_reply(world, "priit", asked)
    assert keeper is not None and keeper.text.startswith("Yes, I can do that (print3d)")
    other = direct_reply(world, "hana", asked.replace("Priit", "Hana"))
    assert other is not None and other.text.startswith("Sorry, I can't help with that (print3d)")
    # a question about the machine asks nothing of them
    free = direct_reply(world, "priit", "Hi Priit, is the 3D printer free?")
    assert free is not None and "can do that" not in free.text


def test_in_the_group_only_the_machines_keeper_volunteers_for_it() -> None:
    world = World.from_office(fablab())
    everyone = [p.id for p in fablab().people]
    asked = "Hi all, could anyone run Ines Varga's design file through the laser cutter?"
    assert [r.person for r in group_replies(world, everyone, asked)] == ["priit"]
