"""A message opened by the speaker's initials or name and a colon ("JL: send my layout to
Bjorn so he can start on p7", from Jean-Luc, called "JL") is signed on: the sign-on is read
away, a name typed without its diacritics ("Bjorn" for Björn) is that colleague, and "so he
can ..." is the purpose, its "he" the recipient just named (blind rounds 61-62's class: "Who
should I pass your file on to?"). The sign-on never changes who asks: the same text from
another colleague sends their own layout."""

from __future__ import annotations

import pytest

from helpers.match_desk import match_desk
from helpers.reading import frame_reader

_frame = frame_reader(match_desk, "jeanluc")


@pytest.mark.parametrize(
    "text",
    [
        "JL: send my layout to Bjorn so he can start on p7",
        "JL: can you send my layout over to bjorn so he can get going on p7",
        "J.L.: send my layout to Björn",
        "Jean-Luc: send Bjorn my layout so he can start on page 7",
        "JR: pass my layout on to Bjorn so he can start on p7",
    ],
)
def test_a_sign_on_is_read_away(text: str) -> None:
    frame = _frame(text)
    assert frame.decline is None and frame.question is None, frame
    assert [(t.kind, t.owner, t.recipient) for t in frame.tasks] == [
        ("send_file", "jeanluc", "bjorn")
    ], frame


def test_a_sign_on_never_changes_who_asks() -> None:
    frame = _frame("JL: send my layout to Bjorn so he can start on p7", "dara")
    assert [(t.kind, t.owner, t.recipient) for t in frame.tasks] == [
        ("send_file", "dara", "bjorn")
    ], frame


@pytest.mark.parametrize(
    "text", ["FYI: the kettle is broken", "NB: the shredder's making a grinding noise"]
)
def test_no_ones_initials_are_read_as_before(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and "Thanks for letting me know" in frame.decline, frame
