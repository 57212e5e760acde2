"""A pronoun subject after a named person's state, joined by "and"/"so"/"but" (class 72j-4):
"Chen is cold and she needs a coffee" was answered "Noted. I did nothing." (the need folded
into the statement). The need is a clause of its own: the pronoun is the one person named
before, and the need is restated and asked as "Chen needs a coffee" is; with two named,
whom it means is asked."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import OfficeOf, frame_reader

_default = frame_reader(default_office, "zhang")
_harbour = frame_reader(harbour_office, "will")


@pytest.mark.parametrize(
    ("text", "question"),
    [
        ("Chen is cold and she needs a coffee", "Shall I get coffee for Chen Jie?"),
        ("Chen is cold so she needs a coffee", "Shall I get coffee for Chen Jie?"),
        ("Lee is tired, and he needs a coffee", "Shall I get coffee for Lee Ming?"),
    ],
)
def test_the_need_after_a_state_is_restated_and_asked(text: str, question: str) -> None:
    frame = _default(text)
    assert frame.tasks == [] and frame.question == question, frame
    # the same question as the need said with the name
    named = "Lee needs a coffee" if "Lee" in question else "Chen needs a coffee"
    assert _default(named).question == question


@pytest.mark.parametrize(
    ("text", "question"),
    [
        ("Grace is busy so he needs a highlighter", "Shall I bring a highlighter to Grace Huang?"),
        ("Mark is cold but he wants a tea", "Shall I get tea for Mark Lindqvist?"),
    ],
)
def test_on_harbour_too(text: str, question: str) -> None:
    frame = _harbour(text)
    assert frame.tasks == [] and frame.question == question, frame


@pytest.mark.parametrize(
    ("office", "text", "question"),
    [
        (
            default_office,
            "Chen and Lee are cold and she needs a coffee",
            "Who do you mean by 'she': Chen Jie or Lee Ming?",
        ),
        (
            harbour_office,
            "Grace and Mark are busy so he needs a highlighter",
            "Who do you mean by 'he': Grace Huang or Mark Lindqvist?",
        ),
    ],
)
def test_with_two_named_whom_it_means_is_asked(office: OfficeOf, text: str, question: str) -> None:
    frame = frame_reader(office, "zhang" if office is default_office else "will")(text)
    assert frame.tasks == [] and frame.question == question, frame


def test_a_request_with_a_need_beside_it_is_read_as_before() -> None:
    frame = _default("bring Chen a coffee and she needs a stapler too")
    assert frame.question is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("produce", "coffee", "chen"),
        ("transfer", "stapler", "chen"),
    ]


def test_a_need_of_a_thing_said_before_is_no_new_need() -> None:
    # "she needs it": no thing named, nothing to restate
    frame = _default("Chen is cold and she needs it")
    assert frame.tasks == [] and frame.question is None, frame
