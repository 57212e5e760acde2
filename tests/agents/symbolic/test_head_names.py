"""A bare noun that heads several of one item type's names is that type
(``reading.head_names``): "is there any gel going?" where the sanitiser is also "hand gel"
and "alcohol gel". A noun heading two types' names ("roller": a paint roller and a lint
roller) is asked about, never guessed; one heading a single name ("dispenser" of harbour's
tape dispenser), a facility's name too ("machine" of the default office's coffee machine and
stapling machine), or a unit ("pad") keeps its reading; and a head said as someone's where
no one owns one ("my notes" beside the cupboard's sticky notes) is no guess to make."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.head_names import head_names, head_of, shared_types
from assistantx.core.task_schema import TaskFrame
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader
from helpers.stores_cupboard import stores

_stores = frame_reader(stores, "ada")
_default = frame_reader(default_office, "mao")
_harbour = frame_reader(harbour_office, "pat")


def _tasks(frame: TaskFrame) -> list[tuple[str, str | None, str | None]]:
    return [(t.kind, t.item, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    ("text", "item", "to"),
    [
        ("bring me some gel", "sanitiser", "ada"),
        ("gel for Tomas please", "sanitiser", "tomas"),
        ("could you bring Tomas some gel", "sanitiser", "tomas"),
        ("bring me some notes", "sticky_notes", "ada"),
    ],
)
def test_a_head_of_one_types_names_is_that_type(text: str, item: str, to: str) -> None:
    frame = _stores(text)
    assert frame.question is None and frame.decline is None, (frame.question, frame.decline)
    assert _tasks(frame) == [("transfer", item, to)]


@pytest.mark.parametrize("text", ["do we have any gel?", "is there any gel?"])
def test_a_question_by_the_head_is_answered_for_the_type(text: str) -> None:
    question = _stores(text).question or ""
    assert question.startswith("There is some hand sanitiser in the stores cupboard."), question


def test_any_gel_going_is_a_want_of_the_type() -> None:
    # "any X going?" of a supply the office holds is a want (``screen.supply_going``)
    frame = _stores("is there any gel going?")
    assert frame.question is None and frame.decline is None, (frame.question, frame.decline)
    assert _tasks(frame) == [("transfer", "sanitiser", "ada")]


@pytest.mark.parametrize(
    ("text", "names"),
    [
        ("bring me a roller", ("paint roller", "lint roller")),
        ("could you get me a roller please", ("paint roller", "lint roller")),
        ("bring me some paper", ("scrap paper", "copier paper")),
    ],
)
def test_a_head_of_two_types_is_asked(text: str, names: tuple[str, ...]) -> None:
    frame = _stores(text)
    assert frame.tasks == [], frame.tasks
    assert all(n in (frame.question or "") for n in names), frame.question


@pytest.mark.parametrize(
    ("office", "text", "item"),
    [
        ("default", "can you get me a machine", "stapler"),  # heads a facility's name too
        ("default", "bring me the machine", "stapler"),
        ("harbour", "bring me a dispenser pls", "tape"),  # one name only
        ("stores", "bring me a pad", "ink_pad"),  # a unit of anything
        ("stores", "bring me a rub", "sanitiser"),  # one name only ("hand rub")
        ("stores", "take my notes to Tomas", "sticky_notes"),  # no one owns sticky notes
    ],
)
def test_must_not_change_no_guess(office: str, text: str, item: str) -> None:
    read = {"default": _default, "harbour": _harbour, "stores": _stores}[office]
    frame = read(text)
    assert all(t.item != item for t in frame.tasks), _tasks(frame)


def test_default_cable_is_still_its_synonym() -> None:
    assert [(k, i) for k, i, _ in _tasks(_default("bring me a cable"))] == [
        ("transfer", "data_cable")
    ]


def test_head_of_a_name() -> None:
    assert head_of("hand gel") == "gel"
    assert head_of("pad of post its") == "pad"
    assert head_of("drink from the vending machine") == "drink"
    assert head_of("gel") == ""


def test_head_names_table() -> None:
    names = [
        ("hand gel", "sanitiser"),
        ("alcohol gel", "sanitiser"),
        ("hand rub", "sanitiser"),
        ("paint roller", "paint"),
        ("decorating roller", "paint"),
        ("lint roller", "lint"),
        ("tape dispenser", "tape"),
        ("stamp pad", "ink"),
        ("ink pad", "ink"),
        ("stapling machine", "stapler"),
        ("staple gun", "stapler"),
    ]
    one, shared = head_names(names, ["coffee machine"], lambda w: w == "gun")
    assert one == {"gel": "sanitiser", "gels": "sanitiser"}
    assert shared == {"roller": ("paint", "lint")}
    assert shared_types(shared, "rollers") == ("paint", "lint")
    assert shared_types(shared, "paint roller") == ()
