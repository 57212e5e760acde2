"""Wish: about other people or the place, answered in words; nothing is moved."""

from __future__ import annotations

from collections.abc import Callable

from assistantx.agents.symbolic.reading.screen.pieces import Message
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.screen.wish import wish

Read = Callable[[str], Message]


def test_a_wish_about_people_names_the_item_it_protects(terms: Terms, message: Read) -> None:
    msg = message("please keep everyone away from Mao's seal today")
    found = wish(terms, msg, msg.pieces[0], "mao")
    assert found is not None and found.verdict == "wish"
    assert found.message.startswith("Understood: I won't move or hand out the seal")


def test_a_request_is_no_wish(terms: Terms, message: Read) -> None:
    msg = message("bring me Mao's seal")
    assert wish(terms, msg, msg.pieces[0], "lee") is None
