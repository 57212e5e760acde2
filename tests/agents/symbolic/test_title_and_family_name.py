"""A title goes with a family name ("Ms Okafor", "Mr Yang", "Prof. Sato", "mrs okafor"): the
person whose family name it is, where a word is one colleague's family name and another's
given name. Which word is the family name is the office's own data: its titled aliases write
it first (the default office: "Dr. Zhang" of Zhang Wei) or last (harbour: "Dr. Huang" of Grace
Huang); an office with none is read the English way, family name last. A bare name word that
two people share is still asked about."""

from __future__ import annotations

import functools
from typing import Any

import pytest

from assistantx.agents.symbolic.reading.surnames import family_first
from assistantx.core.office import Office, parse_office
from helpers.dataset_offices import HARBOUR_FILE, default_office, harbour_office
from helpers.reading import frame_reader
from helpers.yaml_files import raw_yaml


@functools.cache
def _given_and_family() -> Office:
    """Harbour where one colleague's family name is another's given name (Lina Omar beside
    Omar Haddad), and no alias has a title: the office says nothing of the order."""
    raw: dict[str, Any] = raw_yaml(HARBOUR_FILE)
    for p in raw["people"]:
        if p["id"] == "may":
            p["name"], p["aliases"] = "Lina Omar", []
        elif p["id"] == "mark":
            p["name"], p["aliases"] = "Omar Haddad", []
        else:
            p["aliases"] = [a for a in p["aliases"] if " " not in a]
    return parse_office(raw, "harbour, a family name that is a given name")


def test_the_order_is_the_offices_own() -> None:
    assert family_first(default_office())  # "Dr. Zhang", "Manager Mao"
    assert not family_first(harbour_office())  # "Dr. Huang", "Professor Kowalski"
    assert not family_first(_given_and_family())  # no titled alias: the English order


@pytest.mark.parametrize(
    ("text", "who"),
    [
        ("bring Mr Yang a book", "yang"),  # Yang Lei's family name, Liu Yang's given name
        ("bring Ms Yang a cup", "yang"),
        ("bring Prof. Yang a book", "yang"),
        ("could you take a pen to Dr Yang", "yang"),
        ("bring Dr Liu a cup", "liu"),
        ("Mrs Wang needs a stapler, can you bring her one", "wang"),
    ],
)
def test_default_office_a_title_names_the_family_name(text: str, who: str) -> None:
    frame = frame_reader(default_office, "lee")(text)
    assert [t.recipient for t in frame.tasks] == [who], frame


@pytest.mark.parametrize(
    ("text", "who"),
    [
        ("bring Ms Omar a ruler", "may"),
        ("bring Mr Omar a ruler", "may"),
        ("bring Mr Haddad a ruler", "mark"),
        ("Ms Omar needs her tape back, can you take it from Pat to her", "may"),
    ],
)
def test_english_order_a_title_names_the_family_name(text: str, who: str) -> None:
    frame = frame_reader(_given_and_family, "will")(text)
    assert [t.recipient for t in frame.tasks] == [who], frame


@pytest.mark.parametrize(
    ("text", "who"),
    [
        ("bring Ms Okafor a ruler", "may"),
        ("mrs okafor needs a ruler, can you bring her one", "may"),
        ("Prof. Sato needs a ruler, can you bring her one", "dawn"),
        ("Mr Lindqvist needs a calculator, can you bring him one", "mark"),
    ],
)
def test_harbour_titles_and_family_names(text: str, who: str) -> None:
    frame = frame_reader(harbour_office, "will")(text)
    assert [t.recipient for t in frame.tasks] == [who], frame


@pytest.mark.parametrize(
    ("office", "requester", "text", "asked"),
    [
        (default_office, "lee", "bring Yang a book", "Yang"),  # no title: still asked
    ],
)
def test_must_not_change_a_bare_shared_name_is_asked(
    office: Any, requester: str, text: str, asked: str
) -> None:
    frame = frame_reader(office, requester)(text)
    assert not frame.tasks and asked in (frame.question or ""), frame


def test_a_bare_shared_name_in_english_order_is_the_given_name() -> None:
    # Omar Haddad's given name, Lina Omar's family name, no title anywhere: his
    # (``given_name_meant``)
    frame = frame_reader(_given_and_family, "will")("bring Omar a ruler")
    assert [t.recipient for t in frame.tasks] == ["mark"], frame
