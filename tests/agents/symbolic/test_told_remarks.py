"""Statements that ask nothing are answered in words, never with "What should I do ...?"
(blind round 40's classes; the round's sentences were never read): a remark on the day with a
colleague's name word used as an adjective and the speaker's team's plan ("so misty today,
we'll record the intro on the roof"); an exclamation that is also a colleague's name opening
the speaker's own news ("gosh, I left my stapler at home"); a thing's need for work nobody in
the office does ("the holly by the door needs watering"); and a complaint about whoever owns
a thing ("Whoever's mug this is, ..."). Near misses keep their reading: a request beside any
of them still delivers, a colleague's name still names them."""

from __future__ import annotations

import pytest

from assistantx.core.office import load_office
from helpers.reading import frame_reader
from helpers.roof_garden import roof_garden

_frame = frame_reader(roof_garden, "rosa")


@pytest.mark.parametrize(
    "text",
    [
        # a remark on the day, the team's own plan
        "so foggy today, we'll record the intro on the roof. Basil already knows.",
        "so misty today, we'll record the intro on the roof. Basil already knows.",
        "Sunny today, we'll eat outside",
        "such a misty morning",
        "so hot today, we'll work on the roof",
        "we'll record the intro on the roof",
        "so quiet in here today",
        # an exclamation that is also a colleague's name
        "gosh, I left my stapler at home",
        "Gosh, I'm so tired today",
        "wow, I'm so tired today",
        "heck, forgot my mug today",
        # a thing's need for work nobody here does
        "the holly by the door needs watering, it's dropping leaves everywhere",
        "the holly needs to be watered",
        "the fern in reception needs repotting",
        "the basil on the sill needs pruning",
        # whoever owns it
        "Whoever's yoghurt is in the fridge since Friday, it smells awful",
        "Whoever's mug this is, it's been in the sink for days",
        "whoever's stapler is on my desk, please come get it",
        "Whoever's mug this is, take it home",
    ],
)
def test_a_statement_that_asks_nothing_is_answered_in_words(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and frame.decline_outcome == "done", frame


@pytest.mark.parametrize(
    ("text", "item", "owner", "recipient"),
    [
        ("Gosh, can you bring me a stapler?", "stapler", None, "rosa"),
        ("Gosh, can you bring me your stapler?", "stapler", "gosh", "rosa"),
        ("gosh, bring me a stapler", "stapler", None, "rosa"),
        ("bring Gosh a stapler", "stapler", None, "gosh"),
        ("take my mug to Gosh", "mug", "rosa", "gosh"),
        ("Gosh's stapler please", "stapler", "gosh", "rosa"),
        ("so misty today, bring me a mug", "mug", None, "rosa"),
        ("Misty, bring me a mug", "mug", None, "rosa"),
        ("whoever's free, could you bring me a stapler", "stapler", None, "rosa"),
        ("Whoever's stapler this is, can you bring it to Basil", "stapler", None, "basil"),
        ("we'll need a stapler", "stapler", None, "rosa"),
    ],
)
def test_near_misses_keep_their_reading(
    text: str, item: str, owner: str | None, recipient: str
) -> None:
    frame = _frame(text)
    assert frame.decline is None, frame
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [(item, owner, recipient)], (
        frame
    )


def test_a_colleague_named_gosh_is_still_a_person() -> None:
    frame = _frame("Gosh is in the meeting")
    assert frame.tasks == [] and frame.decline is not None
    assert [(h.kind, h.person) for h in frame.hints] == [("availability", "gosh")]


def test_a_colleague_needing_a_thing_is_still_asked() -> None:
    frame = _frame("Holly needs a stapler")
    assert frame.question is not None and "Holly" in frame.question


_default = frame_reader(load_office, "lee")


@pytest.mark.parametrize(
    "text",
    ["dang, I left my stapler at home", "Dang, I'm so tired today", "Zhang, I'm so tired today"],
)
def test_a_name_alone_before_the_speakers_news_asks_nothing(text: str) -> None:
    frame = _default(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and frame.decline_outcome == "done", frame


@pytest.mark.parametrize(
    ("text", "owner"),
    [("Dang, can you bring me your stapler?", "dang"), ("Dang, can you bring me a stapler?", None)],
)
def test_a_name_before_a_request_still_addresses(text: str, owner: str | None) -> None:
    frame = _default(text)
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("stapler", owner, "lee")]
