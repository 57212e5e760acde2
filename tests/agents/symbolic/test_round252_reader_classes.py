"""Blind rounds 252, 254 and 255's classes, read from the measured offices and tested on the
default office and a small prop yard built for them (``helpers.prop_yard``; never the rounds'
offices or sentences):

1. "run off", "run X off Y", "run me off X" ask for printing or copies, never a variant of the
   thing ("some run barcode labels is not something this office makes");
2. a thing left with a role several colleagues hold ("drop it off with the driver") asks which
   of them, and with a role nobody holds asks about the outsider: the drop-off leg is never
   lost and the printout handed to the speaker;
3. "<subject> is back from <Capitalised>" is a return told, whatever the subject's word is in
   the office ("van" of its van keys): nobody called "Pinewood" is asked for;
4. "<colleague>'s run out of <supply>" is that colleague's want of more (asked first, as any
   colleague's need is), never only noted;
5. a machine asked to be brought ("bring me the printer", "a scanner" of the office's document
   scanner) stays where it is: what the speaker wants done with it is asked, never "there is
   no scanner in this office"."""

from __future__ import annotations

import pytest
from _offices import office as office_named

from helpers.prop_yard import prop_yard
from helpers.reading import answered_reader, frame_reader

_default = frame_reader(lambda: office_named("default"), "lee")
_yard = frame_reader(prop_yard, "ada")
_yard_answered = answered_reader(prop_yard, "ada")
_default_answered = answered_reader(lambda: office_named("default"), "lee")


def _tasks(frame: object) -> list[tuple[str, str | None, str | None, str | None]]:
    return [(t.kind, t.operation, t.item, t.recipient) for t in frame.tasks]  # type: ignore[attr-defined]


# -- 1. run off ------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "kind", "item"),
    [
        ("can you run off my report", "print", "file"),
        ("run off my report for me pls", "print", "file"),
        ("run a printout off my file", "print", "file"),
        ("run me off two copies of my contract", "copy", "document"),  # as before
    ],
)
def test_run_off_asks_for_copies_in_the_default_office(text: str, kind: str, item: str) -> None:
    frame = _default(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        (kind, item, "lee", "lee")
    ]


@pytest.mark.parametrize(
    "text",
    [
        "Can you run barcode labels off my stock list?",
        "run me off barcodes for my stock list pls",
        "could you run off barcode labels from my stock list",
    ],
)
def test_a_product_run_off_a_paper_is_made_from_it(text: str) -> None:
    frame = _yard(text)
    assert frame.question is None and frame.decline is None, frame
    assert _tasks(frame) == [("print", "tag", "file", "ada")]


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("run my report over to Wang", [("transfer", None, "document", "wang")]),
        ("I ran out of paper", [("transfer", None, "paper", "lee")]),
    ],
)
def test_other_runs_are_read_as_before(text: str, expected: list[tuple[str, ...]]) -> None:
    frame = _default(text)
    assert frame.question is None, frame
    assert _tasks(frame) == expected


# -- 2. a thing left with a role -------------------------------------------------------------


@pytest.mark.parametrize(
    "text",
    [
        "print my form and drop it off with the driver",
        "print my pick list and drop it off with the driver for the Pinewood run",
        "print my form and give it to the driver",
    ],
)
def test_a_role_two_colleagues_hold_is_asked_which(text: str) -> None:
    frame = _yard(text)
    assert frame.tasks == [] and frame.question is not None, frame
    assert "Bo Lund" in frame.question and "Cy Park" in frame.question


def test_the_driver_named_in_the_answer_gets_the_printout() -> None:
    frame = _yard_answered("print my form and drop it off with the driver", ["Cy Park"])
    assert frame.question is None, frame
    assert _tasks(frame) == [("print", "print", "file", "cy")]


def test_a_role_one_colleague_holds_gets_it() -> None:
    frame = _yard("print my form and drop it off with the manager")
    assert _tasks(frame) == [("print", "print", "file", "di")]
    frame = _default("copy my contract and leave it with the manager")
    assert [(t.kind, t.recipient) for t in frame.tasks] == [("copy", "mao")]


def test_a_thing_left_with_nobody_of_the_office_is_asked_about() -> None:
    """Where nobody is a driver, "drop it off with the driver" is an outsider, as "give it to
    the driver" is: asked, never the printout handed to the speaker."""
    frame = _default("print my form and drop it off with the driver")
    assert frame.tasks == [] and frame.question is not None, frame
    assert "the driver" in frame.question
    # "go through it with the client": no hand-over
    frame = _default("print my report and go through it with the client")
    assert [(t.kind, t.recipient) for t in frame.tasks] == [("print", "lee")]


# -- 3. a return told ------------------------------------------------------------------------


@pytest.mark.parametrize(
    "text",
    [
        "van's back from Pinewood, keys are in the cage",
        "van's back from Pinewood",
        "van is back from Leeds",
    ],
)
def test_a_return_told_asks_for_nobody(text: str) -> None:
    frame = _yard(text)
    assert frame.tasks == [] and frame.question is None, frame


@pytest.mark.parametrize(
    "text",
    ["Wang's back from Shenzhen, her stapler's on her desk", "the van is back from Leeds"],
)
def test_returns_told_in_the_default_office_stay_told(text: str) -> None:
    frame = _default(text)
    assert frame.tasks == [] and frame.question is None, frame


def test_a_name_after_from_in_a_request_is_still_looked_up() -> None:
    assert "Pinewood" in (_yard("get me a torch from Pinewood").question or "")
    frame = _default("get me a stapler from Wang")
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("stapler", "wang", "lee")]


# -- 4. a colleague's supply run out ---------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "who", "item"),
    [
        ("Wang's run out of paper", "Wang Fang", "paper"),
        ("zhang has run out of paper at reception", "Zhang Wei", "paper"),
        ("Wang ran out of wipes", "Wang Fang", "wipes"),
    ],
)
def test_a_colleagues_supply_run_out_is_their_want(text: str, who: str, item: str) -> None:
    frame = _default(text)
    assert frame.decline is None and frame.question is not None, frame
    assert who in frame.question and item in frame.question


def test_said_yes_the_supply_goes_to_them() -> None:
    frame = _default_answered("Wang's run out of paper", ["yes"])
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", "paper", "wang")]
    frame = _yard_answered("Ed's run out of zip ties down at the cage", ["yes"])
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", "ties", "ed")]


@pytest.mark.parametrize(
    ("text", "tasks"),
    [
        ("I've run out of paper", [("transfer", None, "paper", "lee")]),
        ("the printer's run out of paper", []),
        ("Wang's run out of time", []),
        ("Wang has run out of patience", []),
    ],
)
def test_other_things_run_out_are_read_as_before(text: str, tasks: list[tuple[str, ...]]) -> None:
    frame = _default(text)
    assert frame.question is None, frame
    assert _tasks(frame) == tasks


# -- 5. a machine asked to be brought --------------------------------------------------------


@pytest.mark.parametrize(
    ("reader", "text", "machine", "verb"),
    [
        (_default, "can you bring me the printer", "printer", "print"),
        (_default, "bring me a copier", "printer", "copy"),
        (_yard, "can you bring me a scanner", "scanner", "scan"),
    ],
)
def test_a_machine_stays_where_it_is_and_its_work_is_asked(
    reader: object, text: str, machine: str, verb: str
) -> None:
    frame = reader(text)  # type: ignore[operator]
    assert frame.tasks == [] and frame.decline is None, frame
    assert frame.question is not None and f"The {machine} is" in frame.question
    assert "stays where it is" in frame.question and f"shall I {verb} something" in frame.question


@pytest.mark.parametrize(
    "text", ["bring me a stapler", "bring me a coffee from the coffee machine"]
)
def test_things_asked_to_be_brought_are_read_as_before(text: str) -> None:
    frame = _default(text)
    assert frame.question is None and len(frame.tasks) == 1, frame
