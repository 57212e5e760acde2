"""A possessive naming someone outside the office (a title and a surname nobody here has, "mr
okafor's", or a noun of outsiders with its article dropped, "client's") describes whose the thing
is outside: nobody to ask about ("I don't know anyone called 'okafor'"); the rest of the message
is read (``readings._unknown_name``, ``speech`` statements). A colleague's own surname after a
title, and an unknown bare name, keep their readings."""

from __future__ import annotations

import pytest

from helpers.glazing_lab import glazing_lab
from helpers.reading import frame_reader

_frame = frame_reader(glazing_lab, "ada")


def _tasks(text: str) -> list[tuple[str | None, str | None, str | None, str | None]]:
    return [(t.kind, t.item, t.owner, t.recipient) for t in _frame(text).tasks]


@pytest.mark.parametrize(
    "text",
    [
        "mr okafor's order is sitting in my tray, can it go through the glazer",
        "Mrs Bello's order is sitting in my tray, can it be glazed",
    ],
)
def test_a_titled_strangers_thing_is_context_and_the_own_tray_is_glazed(text: str) -> None:
    frame = _frame(text)
    assert frame.question is None and frame.decline is None, frame
    assert _tasks(text) == [("heat", "tray", "ada", "ada")]


@pytest.mark.parametrize(
    "text",
    [
        "client's laptop lost a key, need something to prise it back on with",
        "customer's laptop lost a key, need something to prise it back on with",
        "patient's laptop is broken, need something to prise it open with",
    ],
)
def test_an_outsiders_thing_with_no_article_is_context(text: str) -> None:
    frame = _frame(text)
    assert frame.question is None, frame
    assert _tasks(text) == [("transfer", "spudger", None, "ada")]


def test_a_colleagues_surname_after_a_title_keeps_its_reading() -> None:
    # must not change: Mr Okoro is Tunde Okoro
    assert _tasks("mr okoro's tray needs glazing") == [("heat", "tray", "tunde", "tunde")]


def test_an_unknown_bare_name_is_still_asked_about() -> None:
    # must not change: no title, no noun of outsiders: who is meant is asked
    frame = _frame("okafor's laptop lost a key, need something to prise it back on with")
    assert frame.question is not None and "okafor" in frame.question, frame


def test_a_titled_strangers_thing_asked_for_is_still_asked_about() -> None:
    # must not change: the stranger's thing is what is asked for, and nobody here keeps it
    frame = _frame("bring me mr okafor's order")
    assert not frame.tasks and frame.question is not None and "okafor" in frame.question, frame
