""" "the Station Officer": a colleague called by the rank the office writes before their
surname ("Station Officer Delaney") is that person, where one person holds the rank (blind
round 26's class, on an office no sentence was written for, ``helpers.watch_room``). A rank
two people hold is nobody's name, and initials ("SO") are no words people say."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.lexicon import rank_titles
from helpers.reading import frame_reader
from helpers.watch_room import watch_room

_frame = frame_reader(watch_room, "kemal")


def test_only_a_rank_one_person_holds_is_a_name() -> None:
    assert rank_titles(watch_room()) == {"station officer": frozenset({"frank"})}


@pytest.mark.parametrize(
    "text",
    [
        "send my stock count spreadsheet to the Station Officer",
        "can you pass my spreadsheet on to the station officer pls",
    ],
)
def test_the_rank_names_its_holder(text: str) -> None:
    frame = _frame(text)
    assert frame.question is None, frame
    assert [(t.kind, t.owner, t.recipient) for t in frame.tasks] == [
        ("send_file", "kemal", "frank")
    ], frame


def test_a_rank_two_hold_names_nobody() -> None:
    frame = _frame("send my spreadsheet to the watch manager")
    assert frame.tasks == [], frame
    assert frame.question is not None
