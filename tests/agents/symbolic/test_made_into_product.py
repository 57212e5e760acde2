"""The product said after "as"/"into"/"on" (an article between or not) chooses the operation
whose product it is, where the plain service's verb ("print") is only the means: "print my
artwork as a pull-up banner" is the large-format printer's banner, not a printout (round
160, class 2; ``reading.made_into``). A product no operation makes, or a word that is no
product, leaves the plain service."""

from __future__ import annotations

from typing import Any

import pytest

from assistantx.core.office import Office, parse_office
from helpers.dataset_offices import DEFAULT_FILE, HARBOUR_FILE
from helpers.reading import frame_reader
from helpers.repro_room import repro_room
from helpers.yaml_files import raw_yaml

_repro = frame_reader(repro_room, "bram")


def _with_a_plotter(path: Any, name: str, desk: str, guard: str) -> Office:
    """A dataset office with a plotter that prints a file as a wall chart (a product the
    office did not have), beside its ordinary printer."""
    raw: dict[str, Any] = raw_yaml(path)
    raw["item_types"].append(
        {"id": "wall_chart", "name": "wall chart", "kind": "product", "synonyms": ["big chart"]}
    )
    raw["operations"].append(
        {
            "id": "chart",
            "name": "chart run",
            "verbs": ["plot"],
            "input": "file",
            "product": "wall_chart",
        }
    )
    raw["facilities"].append(
        {
            "id": "plotter",
            "name": "plotter",
            "location": desk,
            "operations": ["chart"],
            "guards": [guard],
            "products": ["wall_chart"],
        }
    )
    return parse_office(raw, name)


def _harbour() -> Office:
    return _with_a_plotter(HARBOUR_FILE, "harbour with a plotter", "copy_room", "ray")


def _default() -> Office:
    return _with_a_plotter(DEFAULT_FILE, "default with a plotter", "print_room", "xu")


_harbour_frame = frame_reader(_harbour, "may")
_default_frame = frame_reader(_default, "zhou")


@pytest.mark.parametrize(
    ("text", "operation"),
    [
        # the class's analogues
        ("print my artwork as a pull-up banner", "banner"),
        ("print my slides as a poster", "poster"),
        # variants: "on a", "into a", a synonym, a plural
        ("print my slides on a roll-up banner", "banner"),
        ("print my artwork into a poster please", "poster"),
        ("print my slides as posters", "poster"),
        # the plain service: no product said, one nobody makes, or no product at all
        ("print my slides", "print"),
        ("print my slides as a flyer", "print"),
        ("print my artwork for the poster session", "print"),
        ("print my slides on the printer", "print"),
    ],
)
def test_the_product_said_chooses_the_operation(text: str, operation: str) -> None:
    frame = _repro(text)
    assert [(t.item, t.owner, t.recipient, t.operation) for t in frame.tasks] == [
        ("artwork", "bram", "bram", operation)
    ], frame


@pytest.mark.parametrize(
    ("reader", "requester", "text", "operation"),
    [
        (_harbour_frame, "may", "print my file as a wall chart", "chart"),
        (_harbour_frame, "may", "print my deck on a big chart for Will", "chart"),
        (_harbour_frame, "may", "print my file", "print"),
        (_default_frame, "zhou", "could you print my file as a wall chart?", "chart"),
        (_default_frame, "zhou", "print my file as a favour", "print"),
    ],
)
def test_the_same_on_the_dataset_offices(
    reader: Any, requester: str, text: str, operation: str
) -> None:
    frame = reader(text)
    assert [t.operation for t in frame.tasks] == [operation], frame
