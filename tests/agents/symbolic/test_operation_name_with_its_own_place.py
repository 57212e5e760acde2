"""An operation whose name carries its own preposition and place ("send to the lab", verbs
"courier", "send off") is said in English in every text built from it (blind round 55's class;
its office and sentences were never read): "it" goes after the verb ("send it to the lab",
"send it off"), a destination said replaces the name's own place, and a name of several words
is said by its first declared verb. One-word names read as before ("fax it")."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.core.office import Operation
from assistantx.core.wording import by_means, purpose_text, verb_alone, verb_it, with_object
from helpers.reading import frame_reader
from helpers.vet_yard import vet_yard

_frame = frame_reader(vet_yard, "gwen")

_LAB = Operation(id="a", name="send to the lab", verbs=("courier", "send off"), sends_out=True)
_BARE_LAB = Operation(id="b", name="send to the lab", sends_out=True)
_FAX = Operation(id="c", name="fax", sends_out=True)
_SEND_OFF = Operation(id="d", name="send off", sends_out=True)
_LASER = Operation(id="e", name="laser print")


@pytest.mark.parametrize(
    ("op", "plain", "to_axiom", "bare", "alone", "by"),
    [
        (_LAB, "courier it", "courier it to Axiom", "courier it", "courier", "by courier "),
        (_BARE_LAB, "send it to the lab", "send it to Axiom", "send it", "send", ""),
        (_FAX, "fax it", "fax it to Axiom", "fax it", "fax", "by fax "),
        (_SEND_OFF, "send it off", "send it off to Axiom", "send it off", "send off", ""),
        (_LASER, "laser print it", "laser print it to Axiom", "laser print it", "laser print", ""),
    ],
)
def test_an_operation_is_said_with_it(
    op: Operation, plain: str, to_axiom: str, bare: str, alone: str, by: str
) -> None:
    assert verb_it(op) == plain
    assert verb_it(op, "Axiom") == to_axiom
    assert verb_it(op, bare=True) == bare
    assert verb_alone(op) == alone
    assert by_means(op) == by


def test_an_object_goes_where_it_would() -> None:
    assert with_object("send to the lab", "Gwen's sample") == "send Gwen's sample to the lab"
    assert with_object("send off", "the masks") == "send the masks off"
    assert with_object("print", "Ana's file") == "print Ana's file"


def test_the_code_message_is_english() -> None:
    text = purpose_text(
        vet_yard(),
        "heat",
        "sample:gwen",
        you="gwen",
        operation="lab_send",
        destination="the Axiom lab",
    )
    assert text == "take your blood sample out and courier it to the Axiom lab"


def test_the_questions_of_where_are_english() -> None:
    frame = _frame("courier my blood sample")
    assert frame.question is not None
    assert frame.question.startswith("Where should I courier it to?"), frame
    frame = _frame("courier my blood sample to Ana")
    assert frame.question is not None and "send to the lab" not in frame.question, frame
    assert frame.question.startswith("Should I send it out by courier to Ana outside"), frame


def test_a_service_declined_on_the_wrong_thing_is_english() -> None:
    frame = _frame("test my file")
    assert frame.decline == "Sorry, I can't test a file here: I can only test masks."


async def test_end_to_end_no_text_puts_it_after_the_name() -> None:
    run = await run_instruction(
        vet_yard(), "gwen", "courier my blood sample to the Axiom lab please"
    )
    summary = run.stm.trace.summary
    assert "send to the lab it" not in str(summary), summary
    assert "courier" in str(summary) or run.stm.trace.actions(), summary
