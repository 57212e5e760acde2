"""An ask whether anyone has one of a kind, beside the speaker's own one said to be amiss
(blind round 59-60 class 3; the round's own offices and sentences were never read): "anyone
got a spare pair of earphones? mine just crackle", "mine's dead - anyone got a charger?" ask
for someone else's one for the speaker, its owner asked; "mine" is why they ask, never the
thing asked for (it was read as the speaker's own, to be handed to someone). A question on its
own is still answered in words and offered, and the speaker's own thing that a request works
on is still that thing."""

from __future__ import annotations

import pytest

from helpers.lending_bench import lending_bench
from helpers.reading import frame_reader

_frame = frame_reader(lending_bench, "mira")


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("anyone got a spare pair of earphones? mine just crackle on one side", "headphones"),
        ("anyone got a spare pair of headphones?? mine have packed in lol", "headphones"),
        ("anyone got earphones? mine have packed in", "headphones"),
        ("does anybody have a charger I could borrow, mine's dead", "charger"),
        ("does anyone have a spare charger, mine died", "charger"),
        ("mine's dead - anyone got a charger?", "charger"),
        ("got a spare charger anyone? mine is dead", "charger"),
        ("has anyone got a tape measure? I left mine at home", "tape_measure"),
        ("Has anybody got a spare tape measure? Forgot mine at home.", "tape_measure"),
        ("any chance someone has a spare lamp? my one keeps flickering", "lamp"),
        ("anyone got a spare charger? my charger is dead", "charger"),
    ],
)
def test_someone_elses_one_for_the_speaker(text: str, item: str) -> None:
    frame = _frame(text)
    assert frame.question is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", item, None, "mira")
    ], frame


@pytest.mark.parametrize(
    "text", ["who has a tape measure?", "anyone got a spare lamp?", "has anyone got the lamp?"]
)
def test_a_question_alone_is_answered_and_offered(text: str) -> None:
    frame = _frame(text)
    assert not frame.tasks, frame
    assert frame.question is not None and "Shall I bring you one?" in frame.question, frame
    assert "Mira" not in frame.question and "your" not in frame.question, frame


@pytest.mark.parametrize(
    "text",
    [
        "my lamp is broken, can you take it to Jory",
        "take my lamp to Jory, mine is broken",
        "anyone got a spare lamp? my lamp is broken, please take it to Jory",
    ],
)
def test_the_speakers_own_thing_worked_on_is_still_theirs(text: str) -> None:
    frame = _frame(text)
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("lamp", "mira", "jory")]
