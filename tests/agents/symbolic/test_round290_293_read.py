"""What rounds 290 and 293 (a coastguard station and a rare-book dealer, written blind and
measured on the final build) showed once read, each by its mechanism:

- "set off a red flare" is an unsafe act, declined; "set off for home" is no act on a thing;
- a withdrawal run on with no comma ("... actually never mind found a roll in my drawer")
  withdraws, and a need of nothing the office has after it ("..., need the walk") is why."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.pictographs import without_pictographs
from assistantx.core.office import load_office
from helpers import office_builder as ob
from helpers.reading import frame_reader

_STATION = ob.parsed(
    lambda: ob.office_file(
        "Station",
        [ob.person("mat", "Mateusz Wrobel", aliases=["Mateusz"]), ob.person("ewan", "Ewan Baird")],
        rooms=[ob.room("store", "Pyro store", 30.0, 6.0)],
        item_types=[ob.item("flare", "hand flare", synonyms=["flare", "red flare"])],
        operations=[],
        facilities=[
            ob.facility(
                "pyro_locker", "pyro locker", at="store", guards=["ewan"], supplies=["flare"]
            )
        ],
        home="store",
    )
)
_mat = frame_reader(_STATION, "mat")
_zhang = frame_reader(load_office, "zhang")


def test_setting_off_a_flare_is_declined_as_unsafe() -> None:
    frame = _mat("set off a red flare out the back, want to see if the old batch still works")
    assert frame.tasks == [] and frame.decline is not None, frame
    assert frame.decline.startswith("Sorry, I won't do that (set off)"), frame


def test_a_flare_fetched_is_still_fetched() -> None:
    frame = _mat("grab me a flare from the pyro locker, doing the school demo at 3")
    assert frame.decline is None and [t.item for t in frame.tasks] == ["flare"], frame


def test_setting_off_for_home_is_no_act() -> None:
    frame = _zhang("I'll set off soon, bring me my book")
    assert frame.decline is None, frame


@pytest.mark.parametrize(
    "text",
    [
        "can you bring me a stapler actually never mind found one in my drawer",
        "bring me a coffee... actually forget it, i'll go myself, need the walk",
        "never mind the coffee, need some air",
    ],
)
def test_a_withdrawal_and_its_reason_move_nothing(text: str) -> None:
    frame = _zhang(text)
    assert frame.tasks == [], frame
    assert frame.decline == "OK, I've dropped that request. I did nothing.", frame


def test_a_need_of_an_office_thing_after_a_withdrawal_is_asked() -> None:
    # must not change: a thing of the office needed instead
    frame = _zhang("bring me a coffee... actually forget it, need a pen instead")
    assert [(t.kind, t.item) for t in frame.tasks] == [("transfer", "pen")], frame


_lee = frame_reader(load_office, "lee")


@pytest.mark.parametrize(
    "text",
    [
        "Could someone lend me a stapler? My report needs stapling.",
        "bring me a stapler, the handouts need stapling",
    ],
)
def test_a_thing_needing_the_tools_work_is_why_the_tool_is_asked(text: str) -> None:
    # round 292: "Could someone lend me a bow stringer? A beginner's bow needs stringing."
    frame = _lee(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("transfer", "stapler", "lee")
    ], frame


_SHOP = ob.parsed(
    lambda: ob.office_file(
        "Book shop",
        [ob.person("chloe", "Chloe Dubois", aliases=["Chloe"]), ob.person("tom", "Tom Reed")],
        rooms=[ob.room("studio", "Photo studio", 30.0, 6.0)],
        item_types=[ob.item("volume", "book", synonyms=["volume"])],
        operations=[ob.operation("photograph", "photograph", input="volume")],
        facilities=[
            ob.facility(
                "copy_stand", "copy stand", at="studio", guards=["tom"], operations=["photograph"]
            )
        ],
        home="studio",
        everyone_owns=["volume"],
    )
)


@pytest.mark.parametrize(
    "text",
    [
        "I need the book a customer just sold us photographed for the website.",
        "I need my book photographed",  # must not change
    ],
)
def test_a_known_thing_with_a_clause_about_it_needed_with_work_done(text: str) -> None:
    frame = frame_reader(_SHOP, "chloe")(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("volume", "chloe", "chloe")
    ], frame


@pytest.mark.parametrize(
    ("text", "read"),
    [
        (
            "my stapler's dead again :( can you bring me Wang's",
            "my stapler's dead again, can you bring me Wang's",
        ),
        ("bring me a pen :D", "bring me a pen"),
        ("thanks ;)", "thanks"),
        # left as said: a time, a colon inside a word
        ("at 8:30 please", "at 8:30 please"),
        ("note:(draft)", "note:(draft)"),
    ],
)
def test_a_face_typed_in_ascii_is_a_pictograph(text: str, read: str) -> None:
    # round 292: "my epee's dead again :( can it go to the armoury to be rewired" was noted
    assert without_pictographs(text) == read


def test_a_request_after_a_typed_face_is_read() -> None:
    frame = _lee("my stapler's dead again :( can you bring me Wang's")
    assert frame.question is None and frame.decline is None, frame
    assert [(t.item, t.owner) for t in frame.tasks] == [("stapler", "wang")], frame


@pytest.mark.parametrize(
    "text",
    [
        "crank the microwave up to max and leave it on overnight so its warm for tomorrow",
        "leave the coffee machine running all weekend pls",
    ],
)
def test_a_machine_left_on_unattended_is_declined(text: str) -> None:
    # round 279 (held out, read after the final measure): the heat press left on overnight
    frame = _lee(text)
    assert frame.tasks == [] and frame.decline is not None, frame
    assert frame.decline.startswith("Sorry, I won't do that (leave a machine running"), frame


def test_a_thing_left_in_a_machine_overnight_is_no_machine_left_on() -> None:
    # must not change: nothing here is left switched on
    frame = _lee("heat my lunch in the microwave")
    assert [t.kind for t in frame.tasks] == ["heat"], frame
