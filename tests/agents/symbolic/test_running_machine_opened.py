"""Fixer fix60g class 1: a machine said to be still at work while the speaker asks to open it
or take their thing out of it ("open the kiln now and get my pots out, I know it's still at
900 but I can't wait") is declined in words; main ran the machine's own service on the thing
(fired the pot, heated the lunch) or fetched it. Said without that state, or waiting for the
machine to finish, it reads as before, and never runs the machine's service. Also class 2 on
a studio nobody wrote a sentence for: vague work on the speaker's pot, which three services
take, is asked by naming them."""

from __future__ import annotations

from typing import Any

import pytest

from assistantx.core.office import Office, parse_office
from helpers import office_builder as ob
from helpers.dataset_offices import default_office
from helpers.reading import frame_reader


def _raw_studio() -> dict[str, Any]:
    return ob.office_file(
        "pot studio",
        (ob.person("ines", "Ines Marlow", "pot"), ob.person("rafe", "Rafe Dunn", "pot")),
        rooms=[
            ob.room("kiln_room", "Kiln room", 4.0, 20.0),
            ob.room("photo_room", "Photo room", 14.0, 20.0),
        ],
        item_types=[ob.item("pot", "pot", "personal", synonyms=["bowl", "pots"])],
        operations=[
            ob.operation("fire", "fire", input="pot"),
            ob.operation("glaze", "glaze", input="pot"),
            ob.operation("photograph", "photograph", input="pot"),
        ],
        facilities=[
            ob.facility(
                "kiln", "kiln", at="kiln_room", guards=["rafe"], operations=["fire", "glaze"]
            ),
            ob.facility(
                "camera",
                "camera stand",
                at="photo_room",
                guards=["rafe"],
                operations=["photograph"],
            ),
        ],
        home="kiln_room",
    )


def _studio() -> Office:
    return parse_office(_raw_studio())


_pots = frame_reader(_studio, "ines")
_default = frame_reader(default_office, "lee")


@pytest.mark.parametrize(
    "text",
    [
        "open the kiln now and get my pots out, i know it's still at 900 but i cant wait",
        "empty the kiln please, I know it's still firing",
        "get my bowl out of the kiln while it's still hot",
    ],
)
def test_a_running_kiln_opened_is_declined_in_words(text: str) -> None:
    frame = _pots(text)
    assert frame.tasks == [] and frame.decline is not None and "still at work" in frame.decline


@pytest.mark.parametrize(
    "text",
    [
        "open the microwave and take my lunch out, I know it's still going but I'm starving",
        "pull my pages out of the printer now, I know it's mid-job",
        "get my mug out of the coffee machine while it's still brewing",
    ],
)
def test_a_running_machine_of_the_default_office_is_declined(text: str) -> None:
    frame = _default(text)
    assert frame.tasks == [] and frame.decline is not None and "still at work" in frame.decline


@pytest.mark.parametrize(
    "text",
    [
        "get my lunch out of the microwave",
        "take my lunch out of the oven once it's finished, it's still going",
    ],
)
def test_a_safe_retrieval_is_read_as_before_and_runs_no_service(text: str) -> None:
    frame = _default(text)
    assert [(t.kind, t.operation, t.item) for t in frame.tasks] == [("transfer", None, "lunch")]


def test_a_machine_still_busy_beside_another_errand_is_no_decline() -> None:
    frame = _default("the printer is still busy, bring me a stapler")
    assert [(t.kind, t.item) for t in frame.tasks] == [("transfer", "stapler")]


@pytest.mark.parametrize(
    "text", ["I need my bowl sorted before the crit tomorrow", "can you get my pot seen to"]
)
def test_vague_work_on_a_pot_three_services_take_is_asked(text: str) -> None:
    frame = _pots(text)
    assert frame.tasks == [] and frame.question == (
        "Which should I do with your pot: fire, glaze or photograph?"
    )


def test_fire_my_pot_is_read_as_before() -> None:
    assert [(t.operation, t.item) for t in _pots("fire my pot").tasks] == [("fire", "pot")]
