"""A level or state told, then a request without a stop between them ("my phone's on 2% pls
get me a charging lead"): "pls" with a verb, or "can u"/"could you" with more words, opens
the request of its own (``reading.told_then_asked``); before, the statement swallowed it
("Noted. I did nothing."). And a thing named by another word for its head noun ("charging
lead", "charger cord") is the office's thing of that name (``reading.head_synonyms``): the
default office's data cable is a "charging cable" and a "charger cable" (fix175a class 4)."""

from __future__ import annotations

import copy
import functools

import pytest
from _offices import parser, tasks_of

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import parse_office
from helpers.dataset_offices import DEFAULT_FILE
from helpers.yaml_files import raw_yaml

_CABLE = ("transfer", "data_cable", None, "lee")


@pytest.mark.parametrize(
    "text",
    [
        "my phone's on 2% pls get me a charging lead",
        "my phone's on 2% pls get me a charging cable",
        "my laptop is at 5% can u bring me a charger lead",
        "phone is nearly dead please bring me a charging cord",
    ],
)
def test_the_request_after_the_state_is_read(text: str) -> None:
    assert tasks_of("default", text, "lee") == [_CABLE]


def test_another_request_after_a_state_is_read_too() -> None:
    assert tasks_of("default", "the printer is jammed can you bring me Wang's stapler", "lee") == [
        ("transfer", "stapler", "wang", "lee")
    ]


@pytest.mark.parametrize(
    "text",
    [
        "my phone is dead please",  # no ask after the "please": told
        "my phone is on 2%",
    ],
)
def test_a_state_alone_is_told(text: str) -> None:
    frame = parser("default").parse(text, "lee")
    assert frame.tasks == [] and frame.question is None, frame


def test_a_bare_lead_is_no_cable() -> None:
    frame = parser("default").parse("bring me a pencil lead", "lee")
    assert frame.tasks == [] and frame.decline is not None, frame


@functools.cache
def _usb_lead_office() -> InstructionParser:
    """The default office with its cable named "usb lead" alone."""
    raw = copy.deepcopy(raw_yaml(DEFAULT_FILE))
    for row in raw["item_types"]:
        if row["id"] == "data_cable":
            row["name"], row["synonyms"] = "usb lead", []
    return InstructionParser(parse_office(raw, "default with a usb lead"))


@pytest.mark.parametrize(
    "text", ["usb cable please", "can I borrow a usb cord", "bring me a usb wire"]
)
def test_another_word_for_the_head_noun_names_it(text: str) -> None:
    frame = _usb_lead_office().parse(text, "lee")
    assert [(t.kind, t.item) for t in frame.tasks] == [("transfer", "data_cable")], frame


@pytest.mark.parametrize(
    "text",
    [
        "my laptop's on 5% can someone bring me a charger lead",
        "my laptop is at 5% could anyone bring me a charging cable",
        "my phone's nearly dead can somebody get me a data cable",
    ],
)
def test_an_ask_put_to_anyone_after_a_state_is_read(text: str) -> None:
    """Fix213a class 5: "can someone" opens the ask as "can u" does."""
    assert tasks_of("default", text, "lee") == [_CABLE]


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        # one clause with no told state before the modal: read as before
        ("I can someone bring me a data cable", [_CABLE]),
        ("can someone bring me a data cable", [_CABLE]),
    ],
)
def test_an_ask_to_anyone_with_no_state_before_is_unchanged(
    text: str, expected: list[tuple[str, str, str | None, str]]
) -> None:
    assert tasks_of("default", text, "lee") == expected


# -- fixer fix62c class 2: an ask to anyone, or after a told verb, run on with no stop --------
@pytest.mark.parametrize(
    ("text", "requester", "expected"),
    [
        ("my phone's on 3% anyone got a cable i can borrow", "lee", _CABLE),
        ("my phone's flat anyone have a cable i can use", "lee", _CABLE),
        ("my phone is dead any chance of a cable", "lee", _CABLE),
        # the printer lacks paper: "some" is paper, as after a stop
        (
            "printer's out of paper anyone got some i can use",
            "lee",
            ("transfer", "paper", None, "lee"),
        ),
        # a told clause with a past verb, no copula
        (
            "my stapler broke can u bring me Wang's",
            "zhang",
            ("transfer", "stapler", "wang", "zhang"),
        ),
        ("my cable died could someone bring me a cable", "lee", _CABLE),
    ],
)
def test_a_run_on_ask_after_a_told_clause_is_read(
    text: str, requester: str, expected: tuple[str, str, str | None, str]
) -> None:
    assert tasks_of("default", text, requester) == [expected]


def test_a_run_on_ask_after_where_the_speaker_is_is_read() -> None:
    assert tasks_of("default", "im at my desk all day could someone bring me a coffee", "lee") == [
        ("produce", "coffee", None, "lee")
    ]


@pytest.mark.parametrize(
    "text",
    [
        "my phone's on 3%",
        "my stapler broke yesterday and Wang fixed it",
        "Wang said anyone can borrow his stapler",
    ],
)
def test_a_told_clause_with_no_ask_after_it_stays_told(text: str) -> None:
    frame = parser("default").parse(text, "lee")
    assert frame.tasks == [] and frame.question is None and frame.decline is not None, frame


def test_an_ask_to_anyone_alone_is_read_as_before() -> None:
    frame = parser("default").parse("anyone got a cable?", "lee")
    assert frame.tasks == [] and frame.question is not None and "Shall I" in frame.question


def test_an_ask_reported_after_said_is_not_the_speakers() -> None:
    # the reported words are no request of the speaker's own: no task read
    assert tasks_of("default", "Wang said can you bring him his stapler", "lee") == []


def test_a_facility_lacking_a_thing_gives_no_it() -> None:
    # "it" is the printer, never the paper it lacks
    frame = parser("default").parse("the printer is out of paper, can you fix it", "lee")
    assert frame.tasks == [], frame
