"""How the office sends things out, said in a question about a part of the request, is English
whatever the operations' names look like (blind round 57's class; its offices and sentences were
never read): "I can send things to the exam board", never "by send to the exam board"; a name or
verb that is a noun is a means ("by post", "by courier"); a verb that is none is no means ("by
send")."""

from __future__ import annotations

import functools

import pytest

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import Office, Operation, parse_office
from assistantx.core.wording import by_means, ways_out
from helpers import office_builder as ob
from helpers.bursary import raw_bursary


def _op(name: str, *verbs: str) -> Operation:
    return Operation(id=name.replace(" ", "_"), name=name, verbs=verbs, sends_out=True)


@pytest.mark.parametrize(
    ("ops", "said"),
    [
        ([_op("send to the exam board", "send")], "I can send things to the exam board."),
        ([_op("send", "send")], "I can send things out of the office."),
        ([_op("fax"), _op("courier")], "I can send things out of the office by fax or courier."),
        (
            [_op("post"), _op("send to the lab", "send")],
            "I can send things out of the office by post or send things to the lab.",
        ),
        ([], ""),
    ],
)
def test_the_ways_out_are_said_in_english(ops: list[Operation], said: str) -> None:
    assert ways_out(ops) == said


@pytest.mark.parametrize(
    ("op", "by"),
    [
        (_op("send", "send"), ""),
        (_op("post"), "by post "),
        (_op("send", "dispatch"), "by dispatch "),
    ],
)
def test_a_means_is_a_noun(op: Operation, by: str) -> None:
    assert by_means(op) == by


@functools.cache
def _office() -> Office:
    raw = raw_bursary()
    raw["operations"].append(
        ob.operation(
            "board",
            "send",
            name="send to the exam board",
            input="file",
            sends_out=True,
            destination_asked="which exam board it goes to",
        )
    )
    raw["facilities"][0]["operations"].append("board")
    return parse_office(raw, "bursary with an exam board")


def test_the_question_about_a_part_says_the_ways_out_in_english() -> None:
    frame = InstructionParser(_office()).parse("print my file and then off to the council", "ana")
    assert frame.question is not None and "off to the council" in frame.question, frame
    assert "by send" not in frame.question, frame
    assert "I can send things to the exam board." in frame.question, frame
