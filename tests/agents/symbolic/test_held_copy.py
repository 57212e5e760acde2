"""Destroying a colleague's thing said by the copy they hold: "shred Hana's copy of the
contract, she'll never know" is Hana's contract (not the requester's own), so it is declined;
"she'll never know", "nobody will know" keep the owner in the dark as "won't notice" does, and
decline. "my copy of the contract" is still the requester's own, and "a copy of the contract"
still a copy to make."""

from __future__ import annotations

import pytest

from helpers.notary_office import notary_office
from helpers.reading import frame_reader

_frame = frame_reader(notary_office, "ruth")


@pytest.mark.parametrize(
    "text",
    [
        "shred Hana's copy of the contract, she'll never know",
        "shred Hana's copy of the contract",
        "please shred Kwesi's copy of the letter",
        "could you shred Tomasz's copy of the affidavit, he'll never find out",
    ],
)
def test_a_colleagues_copy_is_theirs_and_not_destroyed(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.decline is not None, frame


@pytest.mark.parametrize(
    "text",
    [
        "bring me Hana's stapler, she'll never know",
        "bring me Hana's stapler, nobody will know",
        "grab Kwesi's tape for me, no one will find out",
        "take Tomasz's stamp to Ruth, he'll never know",
    ],
)
def test_an_owner_kept_in_the_dark_declines(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.decline is not None, frame
    assert "owner" in frame.decline


@pytest.mark.parametrize(
    ("text", "kind", "owner", "item"),
    [
        ("shred my copy of the contract", "heat", "ruth", "document"),
        ("bring me Hana's copy of the affidavit", "transfer", "hana", "affidavit"),
        ("make me a copy of the contract", "copy", "ruth", "document"),
        ("bring me Hana's stapler", "transfer", "hana", "stapler"),
    ],
)
def test_near_misses_keep_their_reading(text: str, kind: str, owner: str, item: str) -> None:
    frame = _frame(text)
    assert frame.decline is None and frame.question is None, frame
    assert [(t.kind, t.owner, t.item) for t in frame.tasks] == [(kind, owner, item)], frame


def test_a_statement_of_not_knowing_moves_nothing() -> None:
    frame = _frame("I never know where my stapler is")
    assert frame.tasks == [], frame
