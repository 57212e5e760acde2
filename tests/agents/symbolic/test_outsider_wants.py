"""A third person who is nobody of the office wants something (class 79a-3): "a visitor wants
a coffee" made a coffee for the speaker at once, and "the courier needs a pen" declined a
courier service. A want said of someone named by what they are ("a visitor", "my guest",
"the courier") is a statement of their need, as "Wang wants a coffee" is: it is met with
"Shall I ...?", and a yes brings the thing to the speaker, who passes it on."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.outsider_need import outsider_subject
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import OfficeOf, answered_reader, frame_reader

_READERS = {
    default_office: frame_reader(default_office, "mao"),
    harbour_office: frame_reader(harbour_office, "will"),
}
_ANSWERED = {
    default_office: answered_reader(default_office, "mao"),
    harbour_office: answered_reader(harbour_office, "will"),
}


@pytest.mark.parametrize(
    ("office", "text", "question", "task"),
    [
        (
            default_office,
            "a visitor wants a coffee",
            "Shall I get coffee for you?",
            ("produce", "coffee", "mao"),
        ),
        (
            default_office,
            "a client wants a coffee",
            "Shall I get coffee for you?",
            ("produce", "coffee", "mao"),
        ),
        (
            default_office,
            "my guest wants a coffee",
            "Shall I get coffee for you?",
            ("produce", "coffee", "mao"),
        ),
        (
            default_office,
            "the courier needs a pen",
            "Shall I bring a pen to you?",
            ("transfer", "pen", "mao"),
        ),
        # variants: plural, a describing word, other offices' things
        (
            default_office,
            "the visitors want coffee",
            "Shall I get coffee for you?",
            ("produce", "coffee", "mao"),
        ),
        (
            harbour_office,
            "my new client needs a calculator",
            "Shall I bring a calculator to you?",
            ("transfer", "calculator", "will"),
        ),
        (
            harbour_office,
            "the plumber needs a ruler",
            "Shall I bring a ruler to you?",
            ("transfer", "ruler", "will"),
        ),
        (
            harbour_office,
            "a visitor wants a tea",
            "Shall I get tea for you?",
            ("produce", "tea", "will"),
        ),
    ],
)
def test_an_outsiders_want_is_asked_and_comes_to_the_speaker(
    office: OfficeOf, text: str, question: str, task: tuple[str, str, str]
) -> None:
    frame = _READERS[office](text)
    assert frame.tasks == [] and frame.question == question, frame
    yes = _ANSWERED[office](text, ["yes"])
    assert [(t.kind, t.item, t.recipient) for t in yes.tasks] == [task]
    no = _ANSWERED[office](text, ["no"])
    assert no.tasks == []


def test_the_speakers_own_want_is_made() -> None:
    frame = _READERS[default_office]("I want a coffee")
    assert frame.question is None
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("produce", "coffee", "mao")]


def test_a_coffee_for_a_visitor_asked_for_is_offered_to_the_speaker() -> None:
    """ "a coffee for my visitor please" is a request: the outsider rule offers it to the
    speaker, as before."""
    frame = _READERS[default_office]("a coffee for my visitor please")
    assert frame.tasks == [] and frame.question is not None
    assert "bring it to you instead" in frame.question


def test_a_colleagues_want_is_unchanged() -> None:
    frame = _READERS[default_office]("Wang wants a coffee")
    assert frame.tasks == [] and frame.question == "Shall I get coffee for Wang Fang?"


def test_a_courier_service_is_still_a_service() -> None:
    """ "courier my parcel": the verb, not the courier; declined where nothing offers it."""
    frame = _READERS[harbour_office]("courier my parcel to the client")
    assert frame.tasks == [] and frame.decline is not None and "courier" in frame.decline


@pytest.mark.parametrize(
    ("subject", "outsider"),
    [
        (["a", "visitor"], True),
        (["my", "new", "client"], True),
        (["the", "visitors"], True),
        (["someone"], False),  # no description: left to the other readings
        (["the", "stapler"], False),
        (["visitor"], False),  # no determiner
        (["the", "guest", "room"], False),  # the person noun only modifies
    ],
)
def test_which_subjects_are_outsiders(subject: list[str], outsider: bool) -> None:
    assert outsider_subject(subject) is outsider
