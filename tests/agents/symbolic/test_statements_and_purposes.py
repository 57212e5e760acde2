"""Statements, complaints, offers and purpose clauses move nothing (blind rounds 34-36's
classes; their offices and sentences were never read): a complaint about a facility with an
interjection before it, where a colleague has gone and when they will be back, a thing offered
to whoever needs it, a purpose or reason beside a request (nothing it names is asked for), a
told sentence before a request (it lends the request no thing), and a variety of the one
thing a facility makes asked from it by name. Near-misses keep their readings. On
``helpers.drafting_office`` and the default office."""

from __future__ import annotations

import functools

import pytest

from assistantx.core.office import load_office
from assistantx.core.task_schema import TaskFrame
from helpers.drafting_office import drafting_office
from helpers.reading import frame_reader

_frame = frame_reader(drafting_office, "odile")
_default = frame_reader(functools.cache(load_office), "lee")


def _words_only(frame: TaskFrame) -> None:
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and frame.decline_outcome == "done", frame


def _tasks(frame: TaskFrame) -> list[tuple[str, str | None, str | None, str | None]]:
    return [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]


# -- B1: a complaint about a facility, an interjection before it ---------------------------


@pytest.mark.parametrize(
    "text",
    [
        "ugh the binder beeped at me again, third time today",
        "argh the binder jammed on me again",
        "urgh, the laminator is making that grinding noise again",
        "the laminator is making that grinding noise again",
        "sigh the scanner chewed my certificate",
        "gah the binder ate half my pages",
    ],
)
def test_a_complaint_about_a_facility_is_answered_in_words(text: str) -> None:
    _words_only(_frame(text))


@pytest.mark.parametrize(
    ("text", "operation"),
    [
        ("can you laminate my permit, the laminator ate the last one", "laminate"),
        ("ugh, can you laminate my permit please", "laminate"),
        ("argh the scanner jammed, can you scan my certificate when it's back", "scan"),
    ],
)
def test_a_request_beside_a_complaint_is_still_a_request(text: str, operation: str) -> None:
    frame = _frame(text)
    assert [t.operation for t in frame.tasks] == [operation], frame


# -- B2: where someone is, and when they will be back ---------------------------------------


@pytest.mark.parametrize(
    "text",
    [
        "Piet's gone down to the river to take samples, back in an hour",
        "Rena has popped over to the bank, back after lunch",
        "Piet went out to the site, should be back by 4",
        "Rena's nipped across to the bakery, back soon",
        "back in an hour",
    ],
)
def test_where_someone_went_and_when_they_are_back_is_answered_in_words(text: str) -> None:
    _words_only(_frame(text))


def test_a_request_beside_someone_gone_is_read_as_before() -> None:
    frame = _frame("Piet's gone down to the river, back in an hour. can you bring me his ruler")
    assert _tasks(frame) == [("transfer", "ruler", "piet", "odile")], frame


def test_the_default_office_says_no_hour() -> None:
    _words_only(_default("Chen's gone down to the river to take samples, back in an hour"))


# -- B3: a thing offered to whoever needs it ------------------------------------------------


@pytest.mark.parametrize(
    "text",
    [
        "my stapler's on my desk if anyone needs it",
        "there's spare tape on my desk if anybody wants some",
        "left my ruler on the copy room shelf if someone needs one",
        "my stapler is on my desk if anyone else needs it",
        "spare tape on my desk if anyone needs it",
        "my stapler's free if anyone needs it",
    ],
)
def test_an_open_offer_is_answered_in_words(text: str) -> None:
    _words_only(_frame(text))


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("bring me a stapler if you can", [("transfer", "stapler", None, "odile")]),
        ("bring me the tape if anyone needs it", [("transfer", "tape", None, "odile")]),
        ("can you bring Rena my stapler, she needs it", [("transfer", "stapler", "odile", "rena")]),
    ],
)
def test_a_request_with_a_condition_stays_a_request(
    text: str, expected: list[tuple[str, str | None, str | None, str | None]]
) -> None:
    assert _tasks(_frame(text)) == expected


# -- B4: a purpose or reason names nothing asked for ----------------------------------------


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("get me Chen's book pls, need it for the report", [("transfer", "book", "chen", "lee")]),
        ("get me a pen, I need it for the form", [("transfer", "pen", None, "lee")]),
        (
            "Forward my file to Chen so he can book the courier",
            [("send_file", "file", "lee", "chen")],
        ),
        ("print my file so I can read it on paper", [("print", "file", "lee", "lee")]),
        ("print my file so that I could go over it with a pen", [("print", "file", "lee", "lee")]),
        (
            "pls copy my document, the client wants a pdf of it",
            [("copy", "document", "lee", "lee")],
        ),
    ],
)
def test_a_purpose_or_reason_adds_no_item(
    text: str, expected: list[tuple[str, str | None, str | None, str | None]]
) -> None:
    frame = _default(text)
    assert frame.question is None and frame.decline is None, frame
    assert _tasks(frame) == expected, frame


@pytest.mark.parametrize(
    ("text", "operation", "recipient"),
    [
        ("pls scan my certificate, the client wants a pdf of it", "scan", "odile"),
        ("laminate my permit so the inspector can see it", "laminate", "odile"),
        ("scan my permit so we can hand it in tomorrow", "scan", "odile"),
    ],
)
def test_what_is_made_for_an_outsiders_want_comes_back(
    text: str, operation: str, recipient: str
) -> None:
    frame = _frame(text)
    assert [(t.operation, t.recipient) for t in frame.tasks] == [(operation, recipient)], frame


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        # a need of a thing of its own is still asked for
        (
            "bring me a ruler, need a stapler too",
            [("transfer", "ruler", None, "odile"), ("transfer", "stapler", None, "odile")],
        ),
        # "so you can ...": the robot's own work, never cut
        ("so can you bring me a ruler", [("transfer", "ruler", None, "odile")]),
    ],
)
def test_a_need_of_its_own_is_still_asked(
    text: str, expected: list[tuple[str, str | None, str | None, str | None]]
) -> None:
    assert _tasks(_frame(text)) == expected


# -- B5: a told sentence lends no item; a variety of a facility's one product ---------------


@pytest.mark.parametrize(
    ("text", "item"),
    [
        (
            "Long day. Meeting at 3 and I skipped lunch. "
            "Can you fetch me a chocolate bar from the vending machine?",
            "snack",
        ),
        (
            "Long day. Meeting at 3 and I skipped lunch. Can you fetch me a snack from the "
            "vending machine?",
            "snack",
        ),
        ("grab me a flat white from the coffee machine", "coffee"),
        ("I forgot my lunch. Bring me some crisps from the vending machine", "snack"),
    ],
)
def test_a_told_sentence_lends_nothing_and_a_variety_is_the_product(text: str, item: str) -> None:
    frame = _default(text)
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("produce", item, "lee")], frame


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("I skipped lunch. Can you heat it up?", [("heat", "lunch", "lee", "lee")]),
        ("Wang dropped his pen. Bring him one", [("transfer", "pen", None, "wang")]),
    ],
)
def test_a_request_that_points_back_still_takes_the_told_thing(
    text: str, expected: list[tuple[str, str | None, str | None, str | None]]
) -> None:
    assert _tasks(_default(text)) == expected


def test_a_thing_of_no_kind_the_facility_makes_is_still_declined() -> None:
    frame = _frame("grab me some chloroform from the coffee machine")
    assert frame.tasks == [] and frame.decline is not None and "chloroform" in frame.decline
