"""A category word ("a drink", "something to write with") for the office's own things, from
the package's small table (``data/categories.yaml``): asked which, never declined when the
office has things of the kind, never guessed; an unknown concrete noun is still declined."""

from __future__ import annotations

import functools
from typing import Any

import pytest

from assistantx.agents.symbolic import InstructionParser
from assistantx.agents.symbolic.reading.categories import (
    CATEGORIES_FILE,
    categories,
    category_named,
)
from assistantx.core import language
from assistantx.core.office import DEFAULT_OFFICE, Office, load_office, parse_office
from helpers.archive import archive
from helpers.bindery import bindery
from helpers.boathouse import boathouse
from helpers.clinic import clinic
from helpers.hostel import hostel, raw_hostel
from helpers.playhouse import playhouse
from helpers.printshop import printshop
from helpers.yaml_files import raw_yaml

_HARBOUR = DEFAULT_OFFICE.parent / "offices" / "harbour" / "office.yaml"


def _offices() -> list[Office]:
    return [
        load_office(),
        load_office(_HARBOUR),
        archive(),
        bindery(),
        boathouse(),
        clinic(),
        hostel(),
        playhouse(),
        printshop(),
    ]


def _people_words(office: Office) -> set[str]:
    """Every word of the office's people's names, aliases and ids, and of its groups."""
    names = [
        *(p.name for p in office.people),
        *(a for p in office.people for a in p.aliases),
        *(p.id for p in office.people),
        *(g.name for g in office.groups),
    ]
    words = {language.fold(w) for n in names for w in n.replace("_", " ").split()}
    return words - {"ms", "mr", "mrs", "dr"}


def _place_names(office: Office) -> set[str]:
    """The office's places and facilities, each by its whole name and id."""
    names = [
        *(loc.name for loc in office.locations),
        *(loc.id for loc in office.locations),
        *(f.name for f in office.facilities),
        *(f.id for f in office.facilities),
        *(s for f in office.facilities for s in f.synonyms),
    ]
    return {language.fold(n.replace("_", " ")) for n in names}


def _table_phrases() -> set[str]:
    raw: dict[str, Any] = raw_yaml(CATEGORIES_FILE)
    phrases = [str(k) for k in raw] + [
        str(w)
        for entry in raw.values()
        for key in entry
        if isinstance(entry[key], list)
        for w in entry[key]
    ]
    return {language.fold(p) for p in phrases}


def _table_words() -> set[str]:
    return {w for phrase in _table_phrases() for w in phrase.split()}


def test_the_table_is_general_english() -> None:
    """Every word of the table is an ordinary English word (the dictionary, or wordfreq)."""
    odd = sorted(w for w in _table_words() if not language.is_word_form(w))
    assert odd == []


def test_the_table_names_nothing_of_any_office() -> None:
    """No word of a person's or group's name, and no place or facility of any office the
    project ships or tests ("coffee" is a general word; "the coffee corner" would be one
    office's): the candidates always come from the office's own item types."""
    for office in _offices():
        people = _table_words() & _people_words(office)
        places = _table_phrases() & _place_names(office)
        assert not people and not places, (office.name, sorted(people | places))


@pytest.mark.parametrize(
    ("said", "key"),
    [("drink", "drink"), ("drinks", "drink"), ("hot drink", "hot drink"), ("snack", "food")],
)
def test_a_category_is_found_by_its_names(said: str, key: str) -> None:
    found = category_named(said)
    assert found is not None and found.key == key


def test_every_category_has_names_and_members() -> None:
    assert all(c.names and c.members for c in categories())


@functools.cache
def _hostel() -> InstructionParser:
    return InstructionParser(hostel())


@functools.cache
def _default() -> InstructionParser:
    return InstructionParser(load_office())


@pytest.mark.parametrize(
    ("text", "choices"),
    [
        ("bring me a drink", "tea or hot chocolate"),
        ("could I get some drinks please", "tea or hot chocolate"),
        ("get me something to drink", "tea or hot chocolate"),
        ("bring me a hot drink", "tea or hot chocolate"),
    ],
)
def test_a_category_word_asks_which_of_the_offices_things(text: str, choices: str) -> None:
    frame = _hostel().parse(text, "hamid")
    assert not frame.tasks and frame.decline is None
    assert frame.question is not None and choices in frame.question


def test_the_default_offices_drinks_include_the_vending_machines() -> None:
    frame = _default().parse("bring me a drink", "lee")
    assert frame.question is not None and not frame.tasks
    assert "coffee, water or soda from the vending machine" in frame.question


@pytest.mark.parametrize(
    ("answer", "item"),
    [("tea", "tea"), ("hot chocolate please", "cocoa"), ("the tea", "tea")],
)
def test_the_answer_chooses_the_thing(answer: str, item: str) -> None:
    frame = _hostel().parse_with_answers("bring me a drink", "hamid", [answer])
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("produce", item, "hamid")]


@pytest.mark.parametrize(
    "text",
    [
        "bring me a unicorn",  # a concrete thing nobody here has
        "bring me a snack",  # a category the hostel has nothing of
    ],
)
def test_a_thing_or_category_the_office_lacks_is_still_declined(text: str) -> None:
    frame = _hostel().parse(text, "hamid")
    assert frame.decline is not None and not frame.tasks


def _with_marker() -> InstructionParser:
    """The hostel where Mei also has a whiteboard marker (no purpose declared)."""
    raw = raw_hostel()
    raw["item_types"].append({"id": "marker", "name": "whiteboard marker"})
    for p in raw["people"]:
        if p["id"] == "mei":
            p["owns"] = [*p["owns"], {"type": "marker"}]
    return InstructionParser(parse_office(raw, "hostel-marker"))


def test_something_to_write_with_asks_about_the_offices_writing_things() -> None:
    frame = _with_marker().parse("can you get me something to write with", "hamid")
    assert not frame.tasks and frame.question is not None
    assert "whiteboard marker" in frame.question


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("bring me a tea", "tea"),  # the thing itself: made as before
        ("get me something to write with", "pen"),  # a declared purpose: as before
    ],
)
def test_a_named_thing_or_a_declared_purpose_is_read_as_before(text: str, item: str) -> None:
    parser = _hostel() if item == "tea" else _default()
    frame = parser.parse(text, "hamid" if item == "tea" else "lee")
    assert frame.question is None, frame.question
    assert [t.item for t in frame.tasks] == [item]
