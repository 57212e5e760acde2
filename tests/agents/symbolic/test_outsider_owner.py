"""Someone outside the office, named in a reason or a description, is no colleague (blind
round 109's class; its own sentences were never read). An owner named by a common noun ("the
chiropodist's", "the plumber's": any noun, no list) or by a title and a surname the office
does not have ("Mr Jones's address") is context: never a name to ask about, never a colleague
a pronoun binds to, and a paper of theirs to work on is the speaker's in hand. "to write" is
an infinitive, no destination, so "... to write the client's address with" sends nothing out.
Colleagues named the same way, and a titled stranger owning a thing of the office, are read as
before."""

from __future__ import annotations

import pytest

from helpers.county_court import county_court
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import ReadFrame, frame_reader

_lee = frame_reader(default_office, "lee")
_may = frame_reader(harbour_office, "may")


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("I need a stapler, the client's lost his", "stapler"),
        ("I need a stapler, the client's lost his pen", "stapler"),
        ("I need something to write Mr Jones's address with", "pen"),
        ("I need a pen to write the plumber's address with", "pen"),
        ("I need a pen to write Mrs Baker's name with", "pen"),
        ("I need scissors because the visitor lost his", "scissors"),
        ("I need a pen cos the customer took mine and lost his", "pen"),
    ],
)
def test_an_outsider_in_the_reason_leaves_the_need_alone(text: str, item: str) -> None:
    frame = _lee(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", item, None, "lee")
    ], frame


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("I need a ruler, the courier's lost his", "ruler"),
        ("I need a ruler to check Mrs Baker's drawing with", "ruler"),
        ("I need a ruler since the courier broke his", "ruler"),
    ],
)
def test_the_same_in_harbour(text: str, item: str) -> None:
    frame = _may(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", item, None, "may")
    ], frame


@pytest.mark.parametrize(
    ("read", "text", "kind", "who", "actor"),
    [
        (_lee, "the supplier's invoice needs Zhang's signature", "sign", "lee", "zhang"),
        (_lee, "the chiropodist's invoice needs Zhang's signature", "sign", "lee", "zhang"),
        (_lee, "the chiropodist's invoice needs stamping", "seal", "lee", None),
        (_may, "the chiropodist's invoice needs signing by Will", "sign", "may", "will"),
        (_may, "the plumber's quote needs Mark's signature", "sign", "may", "mark"),
    ],
)
def test_an_outsiders_paper_is_the_speakers_to_have_worked_on(
    read: ReadFrame, text: str, kind: str, who: str, actor: str | None
) -> None:
    frame = read(text)
    assert [(t.kind, t.item, t.owner, t.recipient, t.actor) for t in frame.tasks] == [
        (kind, "document", who, who, actor)
    ], frame


# neighbours: colleagues, a titled stranger's thing of the office, a home outside
def test_a_colleague_who_lost_his_is_still_the_recipient() -> None:
    frame = _lee("Wang's lost his stapler, bring him mine")
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "stapler", "lee", "wang")
    ], frame


def test_a_colleagues_thing_is_still_theirs() -> None:
    frame = _lee("I need Zhang's stapler")
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "stapler", "zhang", "lee")
    ], frame


def test_a_titled_strangers_thing_of_the_office_is_still_asked_about() -> None:
    frame = _lee("bring me Mr Smith's stapler")
    assert frame.tasks == [] and frame.question is not None and "Smith" in frame.question, frame


@pytest.mark.parametrize(
    ("read", "text"),
    [
        (_lee, "take my book to the client's house"),
        (_may, "take my umbrella to the client's flat"),
    ],
)
def test_a_place_outside_is_still_declined(read: ReadFrame, text: str) -> None:
    frame = read(text)
    assert frame.tasks == [] and frame.decline is not None, frame
    assert "outside the office" in frame.decline, frame


def test_a_possessive_cut_off_without_a_reason_is_still_asked() -> None:
    frame = _lee("give the stapler to his")
    assert frame.tasks == [] and frame.question is not None, frame
    assert "cut off" in frame.question, frame


def test_a_word_of_the_offices_own_names_is_no_outsider() -> None:
    # "the Judge's Clerk" is someone of the county court: "the judge's" is asked about
    frame = frame_reader(county_court, "tess")("bring me the judge's keys")
    assert frame.tasks == [] and frame.question is not None, frame
