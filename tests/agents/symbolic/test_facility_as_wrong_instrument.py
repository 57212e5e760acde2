"""A facility named as the instrument ("in/with/on the <facility>") of a verb none of its
services does ("melt down the old mugs in the microwave", "shred my stapler in the printer") is
declined, naming what the facility does; never its product made and handed over, nor its own
service run (fix180a class 2). Its own verbs, placing verbs and making verbs read as before."""

from __future__ import annotations

from typing import Any

import pytest

from assistantx.core.office import load_office
from helpers import office_builder as ob
from helpers.dataset_offices import harbour_office
from helpers.reading import frame_reader


def _raw_lab() -> dict[str, Any]:
    """A small lab: a centrifuge that spins samples, and a kettle that makes tea."""
    return ob.office_file(
        "lab",
        (ob.person("ada", "Ada Byrne"), ob.person("ben", "Ben Okoro")),
        rooms=[ob.room("bench", "Bench", 4.0, 4.0), ob.room("kitchen", "Kitchen", 12.0, 4.0)],
        item_types=[
            ob.item("sample", "sample", "personal"),
            ob.item("tea", "tea", "product"),
            ob.item("pipette", "pipette"),
        ],
        operations=[
            ob.operation("spin", "spin", input="sample"),
            ob.operation("brew", "brew", name="make tea", product="tea"),
        ],
        facilities=[
            ob.facility(
                "centrifuge", "centrifuge", at="bench", guards=["ben"], operations=["spin"]
            ),
            ob.facility("kettle", "kettle", at="kitchen", guards=["ben"], operations=["brew"]),
        ],
        everyone_owns=["sample"],
        home="bench",
    )


_lee = frame_reader(load_office, "lee")
_may = frame_reader(harbour_office, "may")
_ada = frame_reader(ob.parsed(_raw_lab), "ada")


@pytest.mark.parametrize(
    ("read", "text", "does", "said"),
    [
        (
            _lee,
            "can you melt down the old mugs in the microwave?",
            "microwave can heat",
            "melt down",
        ),
        (_lee, "shred my stapler in the printer", "printer can print", "shred my stapler"),
        (_lee, "shred my document in the printer", "printer can print", "shred my document"),
        (_may, "can you shred the old letters in the scanner?", "scanner can scan", "shred"),
        (_lee, "laminate my stapler in the printer", "printer can print", "laminate my stapler"),
        (_may, "can you wash my mug in the kettle", "kettle can make tea", "wash my mug"),
        (_ada, "could you freeze my sample in the centrifuge", "centrifuge can spin", "freeze"),
        (_ada, "grind my sample with the kettle", "kettle can make tea", "grind my sample"),
    ],
)
def test_work_the_facility_does_not_do_is_declined(
    read: Any, text: str, does: str, said: str
) -> None:
    frame = read(text)
    assert not frame.tasks and frame.question is None, frame
    assert frame.decline is not None and does in frame.decline, frame
    assert f"can't {said}" in frame.decline, frame


@pytest.mark.parametrize(
    ("read", "text", "kind"),
    [
        (_lee, "heat my lunch in the microwave", "heat"),
        (_lee, "put my lunch in the microwave", "heat"),
        (_lee, "could you copy my contract on the copier", "copy"),
        (_lee, "print my file on the printer", "print"),
        (_lee, "get me a coffee from the coffee machine", "produce"),
        (_may, "laminate my badge in the laminator", "heat"),
        (_ada, "spin my sample in the centrifuge", "heat"),
    ],
)
def test_the_facilitys_own_work_is_unchanged(read: Any, text: str, kind: str) -> None:
    frame = read(text)
    assert frame.decline is None and frame.question is None, frame
    assert [t.kind for t in frame.tasks] == [kind], frame
