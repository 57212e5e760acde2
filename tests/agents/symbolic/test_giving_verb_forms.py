"""A giving verb in any of its forms names its recipient (fix135c, class 1): "Would you mind
bringing Drew a coffee?" made the coffee for the requester, because only the bare "bring" was
read as a giving verb, so the name after "bringing" was no indirect object. Whichever form the
verb takes ("bringing" after "would you mind", "fetching", "brought"), the person right after
it with the thing's noun phrase after them is whom the thing is for
(reading/indirect_object.py, ``is_giving_verb``)."""

from __future__ import annotations

import functools

import pytest

from assistantx.agents.symbolic.reading.indirect_object import is_giving_verb
from assistantx.core.office import Office, parse_office
from helpers.dataset_offices import DEFAULT_FILE, default_office, harbour_office
from helpers.reading import ReadFrame, frame_reader
from helpers.yaml_files import raw_yaml


@functools.cache
def _drew_office() -> Office:
    """The default office where Zhang is called Drew Zhang ("drew" is also a past tense)."""
    raw = raw_yaml(DEFAULT_FILE)
    zhang = next(p for p in raw["people"] if p["id"] == "zhang")
    zhang["name"], zhang["aliases"] = "Drew Zhang", []
    return parse_office(raw, "drew")


_drew = frame_reader(_drew_office, "lee")
_default = frame_reader(default_office, "lee")
_harbour = frame_reader(harbour_office, "may")


def _read(frame_of: ReadFrame, text: str) -> list[tuple[str | None, str | None, str]]:
    frame = frame_of(text)
    assert frame.question is None and frame.decline is None, frame
    return [(t.item, t.owner, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    "text",
    [
        "Would you mind bringing Drew a coffee? He's been on the phone with a client all morning.",
        "would you mind bringing Drew a coffee",
        "could you bring Drew a coffee",
    ],
)
def test_a_word_name_after_a_giving_verb_gets_the_thing(text: str) -> None:
    assert _read(_drew, text) == [("coffee", None, "zhang")]


@pytest.mark.parametrize(
    ("text", "task"),
    [
        ("would you mind bringing Wang a coffee", ("coffee", None, "wang")),
        ("would you mind fetching Wang a stapler", ("stapler", None, "wang")),
    ],
)
def test_the_same_in_the_default_office(text: str, task: tuple[str, None, str]) -> None:
    assert _read(_default, text) == [task]


@pytest.mark.parametrize(
    ("text", "task"),
    [
        (
            "Would you mind bringing Hope a tea? She's been on calls all morning",
            ("tea", None, "hope"),
        ),
        ("would you mind bringing Will a ruler", ("ruler", None, "will")),
    ],
)
def test_the_same_in_another_office(text: str, task: tuple[str, None, str]) -> None:
    assert _read(_harbour, text) == [task]


@pytest.mark.parametrize(
    ("text", "task"),
    [
        ("would you mind bringing me a ruler", ("ruler", None, "may")),
        ("Will you bring me a ruler?", ("ruler", None, "may")),  # "Will" the modal
    ],
)
def test_the_requester_is_still_the_recipient_when_said(
    text: str, task: tuple[str, None, str]
) -> None:
    assert _read(_harbour, text) == [task]


def test_a_past_giving_in_a_statement_is_no_request_for_that_person() -> None:
    assert _read(_drew, "Drew brought me a coffee, can you bring Wang one") == [
        ("coffee", None, "wang")
    ]


@pytest.mark.parametrize(
    ("word", "gives"),
    [("bringing", True), ("brought", True), ("fetching", True), ("bring", True), ("mind", False)],
)
def test_giving_verbs_in_any_form(word: str, gives: bool) -> None:
    assert is_giving_verb(word) is gives
