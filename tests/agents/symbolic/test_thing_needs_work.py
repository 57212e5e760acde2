"""A thing of the office said to need work that no operation or task of the office names is
told, never fetched (reading/thing_needs.py). "the cup needs washing" fetched a colleague's
cup for the speaker on the default office, while harbour's "the mug needs washing" said
"Noted" only because harbour has no mug; the gerund after "needs" ("washing", "sharpening"),
a noun of work ("a wash") or "to be" and a participle is how the thing is. Work the office
does ("my document needs printing") and an errand's own verb ("needs moving") still ask."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "lee")
_harbour = frame_reader(harbour_office, "rose")
_NOTED = "Noted. I did nothing."


@pytest.mark.parametrize(
    "text",
    [
        "the cup needs washing",
        "my cup needs washing",
        "the stapler needs refilling",
        "the scissors need sharpening",
        "the cup needs a wash",
        "the cup could do with a good rinse",
        "the stapler needs to be repaired",
    ],
)
def test_work_on_a_thing_of_the_default_office_is_told(text: str) -> None:
    frame = _default(text)
    assert frame.tasks == [] and frame.decline == _NOTED, frame


@pytest.mark.parametrize(
    "text",
    [
        "the umbrella needs drying",
        "this calculator needs charging",
        "the charger needs fixing",
        "my ruler wants straightening",
    ],
)
def test_work_on_a_thing_of_harbour_is_told(text: str) -> None:
    frame = _harbour(text)
    assert frame.tasks == [] and frame.decline == _NOTED, frame


@pytest.mark.parametrize(
    ("text", "tasks"),
    [
        # the office's own work, by its verb: asked for, as before
        ("my document needs printing", [("print", "file", "lee")]),
        ("my document needs to be printed", [("print", "file", "lee")]),
        # told, then a request for another of the thing: the request is read
        ("the cup needs washing, bring me a cup", [("transfer", "cup", "lee")]),
        ("the stapler needs refilling, bring me another one", [("transfer", "stapler", "lee")]),
    ],
)
def test_the_office_s_work_and_a_request_beside_it_are_read_as_before(
    text: str, tasks: list[tuple[str, str, str]]
) -> None:
    frame = _default(text)
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == tasks, frame


def test_an_errand_s_own_verb_and_a_person_s_need_are_read_as_before() -> None:
    # "moving" is a verb of handing on: an errand, not a state
    assert [(t.kind, t.item) for t in _harbour("the ruler needs taking to Mark").tasks] == [
        ("transfer", "ruler")
    ]
    # a person who needs a thing is no thing in need of work: restated and asked
    assert _harbour("Mark needs a ruler").question == "Shall I bring a ruler to Mark Lindqvist?"
