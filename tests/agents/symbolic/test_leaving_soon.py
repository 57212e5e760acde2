"""A colleague said to be about to go ("Owen A is heading to the match", "Dara's off to the
site visit in a bit", "she's on her way to the airport") is still here: a thing asked for
them is taken to them now (blind rounds 61-62's class: they were marked away and nothing was
delivered). Away is still away ("off today", "at the dentist"). A given name shared by two
colleagues with the initial of a surname ("Owen A") is that one person."""

from __future__ import annotations

import pytest

from helpers.match_desk import match_desk
from helpers.reading import frame_reader

_frame = frame_reader(match_desk, "jeanluc")


@pytest.mark.parametrize(
    ("text", "recipient"),
    [
        (
            "Owen A is heading to the match. He's forgotten batteries for the flashgun. "
            "Can you take him some from the kit cabinet?",
            "owena",
        ),
        (
            "Dara is off to the site visit in a bit, she forgot batteries, could you run some "
            "over to her?",
            "dara",
        ),
        ("Dara's off to the dentist, can you bring her some batteries?", "dara"),
        ("Owen Marsh is on his way to the stadium, take him some batteries please", "owenm"),
        ("Björn is about to leave for the airport, can you bring him some batteries", "bjorn"),
    ],
)
def test_someone_about_to_go_still_gets_the_thing(text: str, recipient: str) -> None:
    frame = _frame(text)
    assert frame.decline is None and frame.question is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("transfer", "batteries", recipient)
    ], frame
    assert not [h for h in frame.hints if h.kind == "availability"], frame


@pytest.mark.parametrize(
    "text",
    [
        "Dara is off today, can you take her some batteries",
        "Dara is at the dentist, can you take her some batteries",
        "Dara is away, can you take her some batteries",
    ],
)
def test_someone_away_is_still_away(text: str) -> None:
    frame = _frame(text)
    assert [(h.kind, h.person, h.value) for h in frame.hints] == [
        ("availability", "dara", "away")
    ], frame


@pytest.mark.parametrize(
    ("text", "recipient"),
    [
        ("take my stapler to Owen A", "owena"),
        ("take my stapler to Owen M please", "owenm"),
        ("Owen M needs batteries, can you bring him some", "owenm"),
    ],
)
def test_a_shared_given_name_and_an_initial_is_one_person(text: str, recipient: str) -> None:
    frame = _frame(text)
    assert frame.question is None, frame
    assert [t.recipient for t in frame.tasks] == [recipient], frame


def test_a_shared_given_name_before_an_article_is_still_asked() -> None:
    frame = _frame("give Owen a stapler")
    assert frame.question is not None and "Owen Abbott or Owen Marsh" in frame.question, frame
