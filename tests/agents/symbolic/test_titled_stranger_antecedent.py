"""A person named by a title and a name nobody of the office has ("Mrs Hughes", "Dr Okafor") is
an outsider, like "a client": a later "her"/"him"/"their" with no colleague named is that
outsider, and a thing the speaker needs "for her meeting" is the speaker's to receive (fix210b
class 2: it was "Who do you mean by 'her'?"). A colleague named before the pronoun is still
its antecedent, and a pronoun with none is still asked about."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "lee")


@pytest.mark.parametrize(
    "text",
    [
        "Mrs Hughes is coming in at 3. I need a printout of my report for her meeting before then",
        "Mrs Hughes is coming in at 3. I need a printout of my report for her meeting",
        "Dr Okafor is visiting at 2, I need a copy of my report for her",
        "Ms Lindqvist is in tomorrow. I need a printout of my report for her visit",
        # neighbours that already read so
        "Mr Hughes is coming in at 3. I need a printout of my report for his meeting",
        "a client is coming in at 3. I need a printout of my report for her meeting",
    ],
)
def test_the_thing_is_the_speakers_for_the_outsider(text: str) -> None:
    frame = _default(text)
    assert frame.question is None and frame.decline is None, frame
    assert frame.tasks, frame
    assert {t.recipient for t in frame.tasks} == {"lee"}, frame


def test_a_colleague_named_is_still_the_antecedent() -> None:
    frame = _default("Wang is coming at 3, bring her a coffee")
    assert [(t.item, t.recipient) for t in frame.tasks] == [("coffee", "wang")], frame


@pytest.mark.parametrize(
    "text", ["bring her a coffee", "I need a printout of my report for her meeting"]
)
def test_a_pronoun_with_no_antecedent_is_asked_about(text: str) -> None:
    frame = _default(text)
    assert not frame.tasks, frame
    assert frame.question is not None and "'her'" in frame.question, frame


def test_a_colleague_named_with_a_title_is_still_the_colleague() -> None:
    frame = _default("Mrs Wang is coming in at 3. I need a printout of my report for her")
    assert [(t.kind, t.recipient) for t in frame.tasks] == [("print", "wang")], frame


@pytest.mark.parametrize(
    "text",
    [
        # the outsider's own thing is what the work is for (blind round 210: "Mrs Okafor is
        # coming in at 3. I need a double mount cut ... for her etching" asked who "her" was)
        "Mrs Hughes is coming in at 3. I need some paper for her book before then",
        "a client is coming in at 3. I need a pen for her book",
    ],
)
def test_for_the_outsiders_own_thing_is_the_speakers(text: str) -> None:
    frame = _default(text)
    assert frame.question is None and frame.decline is None, frame
    assert [t.recipient for t in frame.tasks] == ["lee"], frame
    assert all(t.item != "book" for t in frame.tasks), frame


@pytest.mark.parametrize(
    "text",
    [
        "a client is coming in at 3, bring me her book",
        "a visitor is coming at 3. I need a printout of her report",
    ],
)
def test_the_outsiders_thing_itself_is_still_asked_about(text: str) -> None:
    frame = _default(text)
    assert not frame.tasks and frame.question is not None, frame
