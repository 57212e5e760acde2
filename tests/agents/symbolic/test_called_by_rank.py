""" "the Station Officer": a colleague called by the rank the office writes before their
surname ("Station Officer Delaney") is that person, where one person holds the rank (blind
round 26's class, on an office no sentence was written for, ``helpers.watch_room``). A rank
two people hold is nobody's name, and initials ("SO") are no words people say."""

from __future__ import annotations

import pytest

from assistantx.core.ranks import rank_titles
from helpers.reading import frame_reader
from helpers.watch_room import watch_room

_frame = frame_reader(watch_room, "kemal")


def test_only_a_rank_one_person_holds_is_a_name() -> None:
    assert rank_titles(watch_room()) == {
        "station officer": frozenset({"frank"}),
        "watch manager": frozenset({"hazel"}),
    }


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


def test_a_rank_beside_a_name_settles_the_signer() -> None:
    """ "needs the Watch Manager's signature, can you get Hazel to sign it": one person."""
    frame = _frame("my timesheet needs the Watch Manager's signature, can you get Hazel to sign it")
    assert frame.question is None, frame
    assert [(t.kind, t.owner, t.actor) for t in frame.tasks] == [("sign", "kemal", "hazel")]


def test_a_rank_two_hold_names_nobody() -> None:
    frame = _frame("send my spreadsheet to the crew manager")
    assert frame.tasks == [], frame
    assert frame.question is not None


@pytest.mark.parametrize(
    "text",
    [
        "wld you get my BA set servisd and also take my hose to Hazel after",
        "get my breathing set servised pls",
    ],
)
def test_a_soft_c_typed_as_said_is_read(text: str) -> None:
    """ "servisd" for serviced (blind round 26's class): one edit once the soft "c" is
    written as said; on main it was two edits from any word and was left unread."""
    frame = _frame(text, "rob" if "hose" not in text else "kemal")
    assert frame.question is None, frame
    assert frame.tasks[0].operation == "service", frame


@pytest.mark.parametrize(
    "text",
    [
        "my timesheet needs Hazel Quinn's signature, can you get Hazel to sign it",
        "my timesheet needs the Watch Manager's signature, could you get Hazel to sign it",
        "Hazel has to sign my timesheet. can you get her to sign it",
    ],
)
def test_the_signer_named_again_is_no_recipient(text: str) -> None:
    """Blind round 26's eval class: the signer said twice ("needs Hazel's signature, get
    Hazel to sign it") signs, and the signed paper comes back; on main the second naming
    made her the recipient too and the paper stayed with her (a wrong hand-over)."""
    frame = _frame(text)
    assert [(t.kind, t.actor, t.recipient) for t in frame.tasks] == [("sign", "hazel", "kemal")], (
        frame
    )
