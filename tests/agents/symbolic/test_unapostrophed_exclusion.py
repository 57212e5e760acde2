"""An exclusion said with a possessive ("not wangs", "except wangs", "anyone's but Wang's"),
after a request for one: any owner's but that colleague's. "wangs" is Wang's without its
apostrophe, not a typo of Dang/Yang (``lexicon._person_ids``); "anyone's but X's" is said as the
exclusion "not X's" (``reading.excluded_owner``), never X's thing."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office
from helpers.reading import frame_reader

_frame = frame_reader(default_office, "hu")


@pytest.mark.parametrize(
    "text",
    [
        "could u bring me a stapler? not wangs, she's using hers",
        "could u bring me a stapler? except wangs",
        "could u bring me a stapler? anyone's but wangs",
        "could u bring me a stapler, anyone's but Wang's",
        "bring me a stapler anybody's except Wang's",
    ],
)
def test_any_stapler_but_wangs(text: str) -> None:
    frame = _frame(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("stapler", None, "hu")]
    assert any(h.person == "wang" and h.value == "not wanted" for h in frame.hints), frame


def test_a_name_shared_by_two_as_a_given_and_a_family_name_is_asked_between_them_only() -> None:
    frame = _frame("could u bring me a stapler? not yangs, he's using his")
    assert frame.question is not None, frame
    assert "Yang Lei" in frame.question and "Liu Yang" in frame.question, frame
    assert "Dang Hao" not in frame.question and "Wang Fang" not in frame.question, frame


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        ("bring me wangs stapler", "wang"),  # must not change
        ("could u bring me a stapler? not Wang's", None),  # must not change
    ],
)
def test_neighbours_keep_their_reading(text: str, owner: str | None) -> None:
    frame = _frame(text)
    assert [(t.item, t.owner) for t in frame.tasks] == [("stapler", owner)], frame


@pytest.mark.parametrize(
    "text",
    [
        "can anyone but Wang bring me a stapler",
        "could someone other than Wang lend me a stapler?",
        "can anybody except Wang Fang bring me a stapler please",
        "can anyone but wang bring me a stapler. thanks",
    ],
)
def test_a_doer_ruled_out_is_an_owner_ruled_out(text: str) -> None:
    # the one who lends a stapler is its owner: Wang's is not taken, and she is not asked
    frame = _frame(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("stapler", None, "hu")]
    assert any(h.person == "wang" and h.value == "not wanted" for h in frame.hints), frame


@pytest.mark.parametrize(
    "text",
    [
        "anyone but me can do it",  # the speaker, no colleague: as before
        "can anyone bring me Wang's stapler",  # no exclusion: Wang's, as before
    ],
)
def test_no_colleague_ruled_out_leaves_the_message_as_said(text: str) -> None:
    frame = _frame(text)
    assert not any(h.value == "not wanted" for h in frame.hints), frame
