"""A colleague's thing asked for with the owner to be left undisturbed is declined in words
(blind rounds 57-58's class: "take X's thing, she's out today so don't bother her" asked the
owner and, on her yes, took it, though the requester forbade asking her). A mark of leaving
someone alone ("don't bother", "don't disturb", "no need to trouble") skips the owner's yes
when whom to leave alone follows it ("him", "her", "them", or the owner's name); an owner said
to be away in the first clause of a piece ("he's off today so he won't mind") is away as in a
piece of its own. Near misses are read as before: "don't bother bringing it back" (a negation
of its own), "don't bother Kwesi" beside a request for Hana's thing (whom not to ask is not the
owner), "she said it's fine" and "he won't mind" alone (the owner is asked). Those near misses are
checked in test_skipped_consent.py beside the other cases where the owner is still asked."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.core.actions import Move
from helpers.notary_office import notary_office
from helpers.reading import frame_reader

_frame = frame_reader(notary_office, "ruth")


@pytest.mark.parametrize(
    "text",
    [
        "grab Hana's stapler and bring it to me, she's out today so don't bother her",
        "bring me Kwesi's tape, he's busy, don't disturb him",
        "fetch Tomasz's stamp and stamp my affidavit with it, don't bother Tomasz",
        "take Hana's stapler for me, no need to trouble her",
        "don't bother her, just bring me Hana's stapler",
        "borrow Kwesi's tape for me, he's off today so do not bother him",
        # a request by a plain verb first: "use X's stamp on my paper"
        "use Tomasz's stamp on my affidavit, no need to check with him",
        "use Tomasz's stamp on my affidavit, he's out today so don't bother him",
    ],
)
def test_leaving_the_owner_undisturbed_is_declined(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and "own yes" in frame.decline, frame


@pytest.mark.parametrize(
    "text",
    [
        "bring me Hana's stapler, she's off today so she won't mind",
        "grab Kwesi's tape for me, he's out today and he won't mind",
    ],
)
def test_an_owner_said_away_before_a_join_and_their_yes_said_for_them_is_declined(
    text: str,
) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and "own yes" in frame.decline, frame


@pytest.mark.parametrize(
    "text",
    [
        "use Tomasz's stamp on my affidavit",
        "use Tomasz's stamp on my affidavit, don't ask me again",
    ],
)
def test_a_plain_use_of_a_colleagues_seal_still_asks_them(text: str) -> None:
    frame = _frame(text)
    assert frame.decline is None, frame
    assert [(t.kind, t.actor) for t in frame.tasks] == [("seal", "tomasz")], frame


async def test_end_to_end_nothing_moves_and_the_owner_is_not_asked() -> None:
    text = "grab Hana's stapler and bring it to me, she's out today so don't bother her"
    run = await run_instruction(notary_office(), "ruth", text)
    trace = run.stm.trace
    contacts = {getattr(r.action, "contact", None) for r in trace.actions()}
    assert "hana" not in contacts, trace.summary
    assert not any(isinstance(r.action, Move) for r in trace.actions()), trace.summary
