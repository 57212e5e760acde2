"""A modal never takes a verb in -s: a colleague whose name is also a modal ("May", "Will")
before "needs", "wants", "has" is the subject of that verb, so "May needs her tape back" is
May's need now, not the speaker's possible need later. A modal before a bare verb or a
pronoun ("may I borrow a ruler", "will you bring me tape", "I may need a ruler later") is
still the modal."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.modal_subject import modals_as_subjects
from helpers.dataset_offices import harbour_office
from helpers.reading import frame_reader

_HARBOUR = frame_reader(harbour_office, "grace")


@pytest.mark.parametrize(
    ("text", "item", "owner", "who"),
    [
        ("May needs her tape back, can you take it from Pat to her", "tape", "pat", "may"),
        ("May wants a calculator, could you take Dawn's to her", "calculator", "dawn", "may"),
        ("Will needs a ruler, can you take one from Art to him", "ruler", "art", "will"),
        ("Will wants some tape, could you take Max's to him", "tape", "max", "will"),
    ],
)
def test_a_modal_word_before_a_verb_in_s_is_the_colleague(
    text: str, item: str, owner: str | None, who: str
) -> None:
    frame = _HARBOUR(text)
    got = [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]
    assert got == [("transfer", item, owner, who)], frame


@pytest.mark.parametrize(
    ("text", "item"),
    [("may I borrow a ruler", "ruler"), ("will you bring me tape", "tape")],
)
def test_must_not_change_a_modal_before_a_pronoun_asks(text: str, item: str) -> None:
    frame = _HARBOUR(text)
    assert [(t.item, t.recipient) for t in frame.tasks] == [(item, "grace")], frame


@pytest.mark.parametrize("text", ["I may need a ruler later", "May might need a ruler later"])
def test_must_not_change_a_possible_need_later_asks_for_nothing(text: str) -> None:
    assert not _HARBOUR(text).tasks


def test_only_the_word_before_a_verb_in_s_is_read_as_a_subject() -> None:
    said = "may needs tape and i may need a ruler will says".split()
    got = modals_as_subjects(said)
    assert got[0] != "may" and got[5] == "may" and got[9] != "will", got
