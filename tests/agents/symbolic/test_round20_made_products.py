"""Blind rounds 20 to 22, class 2 (its part the reader now reads): a product named by its
operation's own verb form ("labels" of "label"), as the object of another operation's verb on
the same file ("print labels for my recipe"), or of a verb of doing ("can you do the labels"),
asks for that product, made by its own operation; never a printout besides. On sentences of
our own against a kitchen no sentence was written for."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.agents.symbolic.reading.made_objects import MadeObjects
from assistantx.agents.symbolic.reading.tokens import tokenize
from helpers.airside_kitchen import airside_kitchen
from helpers.reading import frame_reader

_frame = frame_reader(airside_kitchen, "odile")

Row = tuple[str, str | None, str | None, str | None, str]


def _tasks(text: str) -> list[Row]:
    return [(t.kind, t.operation, t.item, t.owner, t.recipient) for t in _frame(text).tasks]


def _labels_for(who: str) -> Row:
    return ("print", "label", "doc_file", "odile", who)


@pytest.mark.parametrize(
    ("text", "who"),
    [
        ("print labels for my recipe and take them to Tobin", "tobin"),
        ("print labels for my file", "odile"),
        ("print me labels for my file", "odile"),
        ("print some labels off my file for Tobin", "tobin"),
        ("can you do the labels for my recipe file", "odile"),
        ("can u do the date labels for my chicken recipe and bring them over", "odile"),
    ],
)
def test_labels_named_after_a_print_verb_are_the_label_run(text: str, who: str) -> None:
    """ "print labels": the labels, made by the label printer; no printout."""
    assert _tasks(text) == [_labels_for(who)]


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("print my file", [("print", "print", "doc_file", "odile", "odile")]),
        ("label my file", [_labels_for("odile")]),
        (
            "print my file and label it",
            [("print", "print", "doc_file", "odile", "odile"), _labels_for("odile")],
        ),
        ("photocopy my contract", [("copy", None, "contract", "odile", "odile")]),
    ],
)
def test_a_service_asked_by_its_own_verb_is_read_as_before(text: str, expected: list[Row]) -> None:
    """Near-miss: "print my file" still prints; "label" as a verb still labels."""
    assert _tasks(text) == expected


@pytest.mark.parametrize(
    "text", ["can u print day labels off my recipe file", "can u do the day labels for my recipe"]
)
def test_labels_of_a_kind_the_office_does_not_make_are_offered_not_printed(text: str) -> None:
    """ "day labels": a kind of label the office does not declare; its ordinary labels are
    offered, nothing is printed before a yes (main printed a printout and labels both)."""
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is not None and "labels" in frame.question


@pytest.mark.parametrize(
    "text",
    ["thanks for printing the labels", "don't print labels for my file", "the labels printed fine"],
)
def test_thanks_a_negation_or_a_statement_prints_nothing(text: str) -> None:
    assert _frame(text).tasks == []


@pytest.mark.parametrize(
    ("text", "at", "product"),
    [
        ("print labels", 1, "labels"),
        ("print me two new labels", 4, "labels"),
        ("do the labels", 2, "labels"),
        ("print day labels", 2, "labels"),
        ("label labels", 1, None),  # its own verb before it: not a rival's object
        ("labels please", 0, None),  # nothing before it asks to make it
        ("print. labels", 1, None),  # a sentence break between
    ],
)
def test_product_at_needs_a_rival_verb_before_it(text: str, at: int, product: str | None) -> None:
    made = MadeObjects.from_office(airside_kitchen())
    assert made.product_at(tokenize(text), at, lambda word: False) == product


def test_only_operations_on_the_same_input_are_rivals() -> None:
    """The photocopy's "copy" works on a paper, the printer's "print" on a file: no rivals,
    so "print a copy" is read as before."""
    assert set(MadeObjects.from_office(airside_kitchen()).rivals) == {"labels"}


async def test_the_label_run_is_what_reaches_tobin() -> None:
    run = await run_instruction(
        airside_kitchen(), "odile", "print labels for my recipe and take them to Tobin"
    )
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    codes = [
        (r.action.purpose, r.action.contact, r.action.item)
        for r in run.stm.trace.actions()
        if r.action.type == "send_qr" and not r.refused
    ]
    assert codes == [("produce", "ines", "labels:odile"), ("collect", "tobin", "labels:odile")]
