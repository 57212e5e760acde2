"""A number or letter label after a word ("level 3", "floor 2", "block B", "room 4") that
modifies a following noun is a label, not the office's item of that name: "plot the level 3
drawings for me" prints the requester's drawings, never does something with the laser level;
a plain noun the office does not list after such a label, in a print or copy request, is the
requester's own file or paper, no guess to restate (``reading.number_labels``)."""

from __future__ import annotations

from typing import Any

import pytest

from assistantx.agents.symbolic.reading.number_labels import after_label, is_label
from assistantx.agents.symbolic.reading.tokens import tokenize
from helpers import office_builder as ob
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_PEOPLE = (
    ob.person("rhea", "Rhea Solberg", "level"),
    ob.person("tomas", "Tomas Brandt"),
    ob.person("iris", "Iris Quinlan", "level"),
)


def _raw_site_office(file_words: tuple[str, ...] = ()) -> dict[str, Any]:
    """A site office with a laser level ("level") and a plotter that prints ("plot");
    ``file_words``: more names of the electronic file ("drawings")."""
    return ob.office_file(
        "site office",
        _PEOPLE,
        everyone_owns=["file"],
        rooms=[ob.room("print_room", "Print room", 4.0, 18.0)],
        item_types=[
            ob.item("level", "laser level", synonyms=["level", "line laser"]),
            ob.item("stapler", "stapler"),
            ob.item("file", "electronic file", "electronic", synonyms=["file", "pdf", *file_words]),
            ob.item("printout", "printout", "product", synonyms=["print"]),
        ],
        operations=[ob.operation("print", "print", "plot", input="file", product="printout")],
        facilities=[
            ob.facility(
                "printer",
                "printer",
                at="print_room",
                guards=["tomas"],
                operations=["print"],
                supplies=["stapler"],
            )
        ],
        home="print_room",
    )


_SITE = frame_reader(ob.parsed(_raw_site_office), "rhea")
# the same office where the file is also called "drawings" (an office's own word for it)
_DRAWINGS_SITE = frame_reader(
    ob.parsed(lambda: _raw_site_office(("drawing", "drawings", "plans"))), "rhea"
)
_DEFAULT = frame_reader(default_office, "lee")
_HARBOUR = frame_reader(harbour_office, "will")


def _tasks(frame: object) -> list[tuple[str, str, str | None, str | None]]:
    tasks = getattr(frame, "tasks", [])
    return sorted((t.kind, t.item, t.owner, t.recipient) for t in tasks)


@pytest.mark.parametrize(
    "text",
    [
        "plot the level 3 drawings for me",  # the class's analogue
        "print the level 2 drawings for me",
        "plot the level B sections for me",
        "print the level 4 plans",
    ],
)
def test_a_labelled_item_name_before_a_noun_is_no_item(text: str) -> None:
    frame = _SITE(text)
    assert frame.question is None, frame
    assert _tasks(frame) == [("print", "file", "rhea", "rhea")], frame


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("plot the level 3 drawings for me", [("print", "file", "rhea", "rhea")]),
        ("print the level B plans for me", [("print", "file", "rhea", "rhea")]),
        # the labelled file as the second part of a request
        (
            "bring me Iris's stapler, and plot the level 3 drawings for me",
            [("print", "file", "rhea", "rhea"), ("transfer", "stapler", "iris", "rhea")],
        ),
        # must not change: the level itself, labelled or not, and a pause before the file
        ("bring me the level 3", [("transfer", "level", None, "rhea")]),
        ("bring me Iris's level", [("transfer", "level", "iris", "rhea")]),
    ],
)
def test_a_labelled_item_name_before_another_items_name_names_that_item(
    text: str, expected: list[tuple[str, str, str | None, str]]
) -> None:
    frame = _DRAWINGS_SITE(text)
    assert frame.question is None, frame
    assert _tasks(frame) == expected, frame


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("print the floor 2 plans for me", [("print", "file", "lee", "lee")]),
        ("print the block B drawings for me", [("print", "file", "lee", "lee")]),
        ("copy the room 4 plans for me", [("copy", "document", "lee", "lee")]),
    ],
)
def test_default_office_a_labelled_noun_is_my_paper_to_print(
    text: str, expected: list[tuple[str, str, str, str]]
) -> None:
    frame = _DEFAULT(text)
    assert frame.question is None, frame
    assert _tasks(frame) == expected, frame


def test_harbour_a_labelled_noun_is_my_file_to_print() -> None:
    frame = _HARBOUR("print the floor 3 drawings for me")
    assert frame.question is None, frame
    assert _tasks(frame) == [("print", "file", "will", "will")], frame


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("bring me the level", [("transfer", "level", None, "rhea")]),
        # a label with no noun after it modifies nothing: still the level
        ("bring me the level 3", [("transfer", "level", None, "rhea")]),
        ("bring me Iris's level", [("transfer", "level", "iris", "rhea")]),
    ],
)
def test_must_not_change_the_level_itself(
    text: str, expected: list[tuple[str, str, str | None, str]]
) -> None:
    assert _tasks(_SITE(text)) == expected, _SITE(text)


def test_must_not_change_a_plain_noun_is_still_restated() -> None:
    # no label: the noun is a guess from the work asked, restated before anything is done
    assert _SITE("plot the drawings for me").question == "Shall I print your file for you?"
    assert _DEFAULT("print the plans for me").question == "Shall I print your file for you?"


@pytest.mark.parametrize(
    ("text", "label"),
    [
        ("3", True),
        ("B", True),
        ("2B", True),
        ("B12", True),
        ("a", False),
        ("I", False),
        ("I'd", False),
    ],
)
def test_what_a_label_is(text: str, label: bool) -> None:
    assert is_label(tokenize(f"level {text}")[1]) is label


def test_a_noun_after_a_label() -> None:
    tokens = tokenize("print the floor 2 plans")
    assert after_label(tokens, 4)
    assert not after_label(tokens, 2)
