"""A colleague said to want to borrow, use or have the requester's own thing, then the thing
left at a place (fix61d, class 1): "Sandy wants to borrow my munsell, could you drop it at the
volunteer table" went to the table, and the consent guard refused Sandy the code: a plain
"wants" may be a wish about the thing, so the guard read nobody as its receiver. A want whose
verb is one of having ("wants to borrow", "would like to use", ``core.wanted_to_have``) is a
want of the thing itself: the reader (``named_want``, ``room_receiver``) and the guard
(``recipients``, ``wanted_own``) read that colleague as its receiver, there. A place alone, a
plain wish about the thing and two colleagues who want it name nobody, as before."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.core.actions import SendQR
from assistantx.core.wanted_to_have import want_of_having, wants_to_have
from assistantx.runtime.recipients import named_recipients
from helpers.consent_memory import memory
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_DEFAULT = frame_reader(default_office, "lee")  # Lee Ming owns a book
_DEFAULT_ZHANG = frame_reader(default_office, "zhang")  # Zhang Wei owns a stapler
_HARBOUR = frame_reader(harbour_office, "mark")  # Mark Lindqvist owns a ruler


def _got(frame: object) -> list[tuple[str, str | None, str | None, str]]:
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]  # type: ignore[attr-defined]


@pytest.mark.parametrize(
    ("words", "length"),
    [
        (["wants", "to", "borrow", "my"], 3),
        (["would", "like", "to", "use", "my"], 4),
        (["might", "want", "to", "have", "a"], 4),
        (["needs", "to", "borrow"], 3),
        (["wants", "it", "up", "on"], 0),  # a wish about the thing
        (["wants", "to", "know", "the"], 0),  # no having
        (["would", "like", "a", "stapler"], 0),
    ],
)
def test_a_want_of_having(words: list[str], length: int) -> None:
    assert want_of_having(words) == length
    assert wants_to_have(words) == bool(length)


@pytest.mark.parametrize(
    ("text", "who"),
    [
        # the class's analogue, a helping verb's want and a room nobody sits in
        ("Mao would like to use my book - pop it over to the meeting room", "mao"),
        ("Zhang wants to use my book, take it to the meeting room", "zhang"),
        ("Wang would like to borrow my book, could you take it to the meeting room", "wang"),
    ],
)
def test_default_the_one_who_wants_to_have_it_receives_it_there(text: str, who: str) -> None:
    assert _got(_DEFAULT(text)) == [("transfer", "book", "lee", who)]


@pytest.mark.parametrize(
    ("text", "who"),
    [
        ("Rose would like to use my ruler - pop it over to reception", "rose"),
        ("Rose'd like to borrow my ruler, could you take it to reception", "rose"),
        # read as before: a plain want, a need
        ("Rose wants to borrow my ruler, could you drop it at reception", "rose"),
        ("Rose needs my ruler, could you drop it at reception", "rose"),
    ],
)
def test_harbour_the_one_who_wants_to_have_it_receives_it_there(text: str, who: str) -> None:
    assert _got(_HARBOUR(text)) == [("transfer", "ruler", "mark", who)]


def test_the_want_alone_is_asked_before_anything_moves() -> None:
    # "would like to use" is read as "wants to use", restated and asked, as "wants to borrow"
    for text in ("Rose would like to use my ruler", "Rose wants to borrow my ruler"):
        frame = _HARBOUR(text)
        assert frame.question == "Shall I bring your ruler to Rose Adeyemi?", frame


@pytest.mark.parametrize(
    "text",
    [
        "Wang wants to borrow my stapler, can you drop it at her desk",
        "Wang wants a stapler, drop mine at her desk",
    ],
)
def test_default_must_not_change_her_desk(text: str) -> None:
    assert _got(_DEFAULT_ZHANG(text)) == [("transfer", "stapler", "zhang", "wang")]


def test_the_speakers_own_want_names_nobody() -> None:
    frame = _HARBOUR("I would like to use my ruler")
    assert frame.tasks == [] and frame.question is not None, frame


@pytest.mark.parametrize(
    ("text", "named"),
    [
        ("Rose wants to borrow my ruler, could you drop it at reception", {"rose"}),
        ("Rose would like to use my ruler - pop it over to reception", {"rose"}),
        ("Rose would like to use my ruler, could you drop it at reception", {"rose"}),
        ("Rose needs my ruler, could you drop it at reception", {"rose"}),
    ],
)
def test_the_guard_names_the_one_who_wants_to_have_it(text: str, named: set[str]) -> None:
    assert named_recipients(harbour_office(), memory("mark", text)) == named


@pytest.mark.parametrize(
    "text",
    [
        "drop my ruler at reception",  # a place, no receiver
        "Rose wants it up on the board, drop my ruler at reception",  # a wish about it
        "Rose wants to borrow my ruler, Pat needs it too, drop it at reception",  # two
        "Rose wants to know the time, drop my ruler at reception",  # no having
    ],
)
def test_the_guard_names_nobody_else(text: str) -> None:
    assert named_recipients(harbour_office(), memory("mark", text)) == set()


def test_the_guard_in_the_default_office() -> None:
    said = "Mao would like to use my book - pop it over to the meeting room"
    assert named_recipients(default_office(), memory("lee", said)) == {"mao"}


async def test_end_to_end_the_code_goes_to_the_one_who_wants_to_borrow_it() -> None:
    text = "Rose wants to borrow my ruler, could you drop it at reception"
    run = await run_instruction(harbour_office(), "mark", text)
    trace = run.stm.trace
    assert trace.outcome == "done", trace.summary
    assert run.sim.world.holder["ruler:mark"] == "rose", trace.summary
    codes = [r.action for r in trace.actions() if isinstance(r.action, SendQR) and not r.refused]
    assert any(a.contact == "rose" and a.purpose == "collect" for a in codes), codes
    assert not any(r.refused for r in trace.actions()), trace.summary
