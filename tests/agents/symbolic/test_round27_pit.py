"""Blind round 27's classes on an office no sentence was written for (``helpers.orchestra_pit``):
a verb with its particle the office declares ("run off" my part) is its operation, not an
errand's "run"; a correction breaking off the second request of a sentence withdraws only
that one; a room whose only use is to be in, said as where an item comes from ("from the
practice room"), is no service refused."""

from __future__ import annotations

import pytest

from helpers.orchestra_pit import orchestra_pit
from helpers.reading import frame_reader

_frame = frame_reader(orchestra_pit, "ines")


@pytest.mark.parametrize(
    "text",
    ["Would you run off my part please", "run off my score file", "can you run off my part"],
)
def test_a_declared_particle_verb_asks_for_its_operation(text: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("print", "part", "ines")]


def test_the_plain_verb_still_runs_an_errand() -> None:
    frame = _frame("can you run my part over to Teodor")
    assert [(t.kind, t.recipient) for t in frame.tasks] == [("send_file", "teodor")], frame


@pytest.mark.parametrize(
    "text",
    [
        "could my jacket get steamed, and then can you heat... no sorry, just bring my lunch",
        "steam my jacket then heat... actually no, just bring my lunch",
    ],
)
def test_a_correction_withdraws_only_the_request_it_breaks_off(text: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item) for t in frame.tasks] == [("heat", "jacket"), ("transfer", "lunch")]


def test_a_correction_after_a_trailing_off_is_read_at_its_first_word() -> None:
    """ "fetch X... actually, no, just print": withdrawn at "actually", so nothing of the
    fetch is left (on main the ", no," was read first and the cello was fetched too)."""
    frame = _frame("bring me Teodor's cello... actually, no, just print my part")
    assert [(t.kind, t.item) for t in frame.tasks] == [("print", "part")], frame


@pytest.mark.parametrize(
    "text",
    [
        "could someone bring my cello down from the practice room",
        "bring my cello out of the instrument lockers please",
    ],
)
def test_a_room_an_item_is_taken_from_is_no_service_refused(text: str) -> None:
    frame = _frame(text)
    assert frame.question is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "cello", "ines", "ines")
    ], frame


def test_asking_for_the_rooms_own_use_is_still_refused() -> None:
    frame = _frame("can you warm up in the practice room for me")
    assert frame.tasks == [], frame


@pytest.mark.parametrize(
    ("text", "kind", "item"),
    [
        ("Teodor has the score file, can you get it off him for me?", "send_file", "part"),
        ("can you get the score file off Teodor for me?", "send_file", "part"),
        ("could you borrow a cello off Teodor for me", "transfer", "cello"),
    ],
)
def test_off_a_person_is_from_them(text: str, kind: str, item: str) -> None:
    """ "get it off her" (blind round 27's class): "off" said of a person as "from"; on
    main the file was taken to be the requester's own and whom to send it to was asked."""
    frame = _frame(text, "maud")
    assert frame.question is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        (kind, item, "teodor", "maud")
    ], frame


def test_slang_for_borrowing_asked_for_oneself_borrows_with_the_owners_yes() -> None:
    """ "can i nick X's Y?" (blind round 27's class) was declined as taking people's things."""
    frame = _frame("hey can i nick Teodor's cello for the Ravel? mine's gone walkabout again")
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "cello", "teodor", "ines")
    ], frame


def test_slang_for_taking_told_to_the_robot_is_declined() -> None:
    frame = _frame("nick Teodor's cello for me")
    assert frame.tasks == [] and frame.decline is not None, frame
