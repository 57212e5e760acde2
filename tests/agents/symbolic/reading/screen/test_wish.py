"""Wish: about other people or the place, answered in words; nothing is moved."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.wish import wish
from reading.screen._judge import Judge


def test_a_wish_about_people_names_the_item_it_protects(judged: Judge) -> None:
    found = judged(wish, "please keep everyone away from Mao's seal today", "mao")
    assert found is not None and found.verdict == "wish"
    assert found.message.startswith("Understood: I won't move or hand out the seal")


def test_a_request_is_no_wish(judged: Judge) -> None:
    assert judged(wish, "bring me Mao's seal", "lee") is None
