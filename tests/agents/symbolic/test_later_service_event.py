"""A later step of the thing that names another service of the office ("humidify my exhibit
before it goes on the ESDA", "... so it's ready for the ESDA lift", "... before Cat lifts
it") says when or why the request is wanted: only the service asked before it is run, never
the later one as well, and the machine named picks no operation (fix60f class 1). Two requests
joined ("... and then put it on the ESDA", "before you lift it, humidify ...") stay two."""

from __future__ import annotations

from typing import Any

import pytest

from assistantx.core.office import load_office
from helpers import office_builder as ob
from helpers.dataset_offices import harbour_office
from helpers.reading import frame_reader

# two services on one thing, each at its own machine
_LAB = ob.parsed(
    lambda: ob.office_file(
        "Lab",
        [
            ob.person("ann", "Ann Lee", "exhibit", aliases=["Ann"]),
            ob.person("bob", "Bob Ray", aliases=["Bob"]),
            ob.person("cat", "Cat Ng", aliases=["Cat"]),
        ],
        rooms=[
            ob.room("chamber_room", "Chamber room", 20.0, 6.0),
            ob.room("esda_room", "Bench room", 25.0, 6.0),
            ob.room("lab", "Lab", 30.0, 6.0),
        ],
        item_types=[ob.item("exhibit", "exhibit")],
        operations=[
            ob.operation("humidify", "humidify", input="exhibit"),
            ob.operation("esda", "lift", name="ESDA lift", input="exhibit"),
        ],
        facilities=[
            ob.facility(
                "chamber",
                "humidity chamber",
                at="chamber_room",
                guards=["bob"],
                operations=["humidify"],
            ),
            ob.facility("esda_f", "ESDA", at="esda_room", guards=["cat"], operations=["esda"]),
        ],
        home="lab",
    )
)
_ann = frame_reader(_LAB, "ann")
_lee = frame_reader(load_office, "lee")
_may = frame_reader(harbour_office, "may")


@pytest.mark.parametrize(
    "text",
    [
        "Please humidify my exhibit before it goes on the ESDA.",
        "humidify my exhibit before it goes to the ESDA",
        "humidify my exhibit ahead of its ESDA lift",
        "humidify my exhibit so it's ready for the ESDA lift",
        "humidify my exhibit before Cat lifts it",
        "before it goes on the ESDA, humidify my exhibit",
    ],
)
def test_only_the_first_service_is_run(text: str) -> None:
    frame = _ann(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.operation, t.item) for t in frame.tasks] == [("humidify", "exhibit")], frame


def test_a_later_machine_is_no_destination() -> None:
    # harbour: "to the laminator" was asked about as where the scan should go
    frame = _may("scan my document before it goes to the laminator")
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item) for t in frame.tasks] == [("copy", "document")], frame


@pytest.mark.parametrize(
    ("read", "text", "asked"),
    [
        # must not change: two requests, each run, in the order given
        (_ann, "humidify my exhibit and then lift it", ["humidify", "esda"]),
        (_ann, "before you lift it, humidify my exhibit", ["esda", "humidify"]),
        (_ann, "humidify my exhibit", ["humidify"]),
    ],
)
def test_two_requests_stay_two(read: Any, text: str, asked: list[str]) -> None:
    frame = read(text)
    assert frame.question is None and frame.decline is None, frame
    assert [t.operation for t in frame.tasks] == asked, frame


@pytest.mark.parametrize(
    ("text", "kind"),
    [
        # neighbours on the default office, read as they were
        ("please copy my document before it goes through the printer", "copy"),
        ("heat my lunch before it goes in the fridge", "heat"),
        ("print my report so it's ready for the meeting", "print"),
        ("copy my document before it goes to Acme", "copy"),
    ],
)
def test_default_neighbours(text: str, kind: str) -> None:
    frame = _lee(text)
    assert frame.question is None and frame.decline is None, frame
    assert [t.kind for t in frame.tasks] == [kind], frame


def test_a_later_machine_asked_as_a_second_step_is_still_asked() -> None:
    # "and then put it on the ESDA": a step asked, its operation still to choose
    frame = _ann("humidify my exhibit and then put it on the ESDA")
    assert frame.question == "Which do you mean: humidify or ESDA lift?", frame
