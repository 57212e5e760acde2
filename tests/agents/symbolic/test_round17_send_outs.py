"""Blind round 17's send-outs named in plain English, on a school arts block no sentence
was written for (``helpers.arts_block``; the round's office and sentences were never read):
"sending off to <an outside name>", "send ... off to the exam board (WJEC)", "send ... to
<a firm> to be laundered" are the office's send-out service, with the destination outside
(never a person to look up); a plain "send ... to Bram" stays a hand-over."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.agents.symbolic import InstructionParser
from assistantx.core.office import parse_office
from helpers.arts_block import arts_block, arts_block_dry_cleaning, raw_arts_block
from helpers.reading import frame_reader

_frame = frame_reader(arts_block, "colm")


@pytest.mark.parametrize(
    ("who", "text", "op", "item", "where"),
    [
        (
            "colm",
            "my exam scripts need sending off to Edexcel today, can you sort it",
            "post_out",
            "scripts",
            "Edexcel",
        ),
        (
            "bram",
            "send my scripts off to the exam board (WJEC) please",
            "post_out",
            "scripts",
            "WJEC",
        ),
        ("colm", "could you send my exam scripts away to AQA", "post_out", "scripts", "AQA"),
        (
            "hatty",
            "Send my tunic to Parkside Laundry to be laundered please.",
            "launder",
            "tunic",
            "Parkside Laundry",
        ),
        ("bram", "post my scripts to the exam board (WJEC)", "post_out", "scripts", "WJEC"),
    ],
)
def test_a_plain_send_off_is_the_offices_send_out(
    who: str, text: str, op: str, item: str, where: str
) -> None:
    frame = _frame(text, who)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.operation, t.item, t.owner, t.destination) for t in frame.tasks] == [
        (op, item, who, where)
    ]


def test_a_plain_send_to_a_colleague_stays_a_hand_over() -> None:
    frame = _frame("send my exam scripts to Bram please", "colm")
    assert [(t.kind, t.item, t.recipient, t.destination) for t in frame.tasks] == [
        ("transfer", "scripts", "bram", None)
    ]


def test_sent_off_to_a_colleagues_name_is_asked_about() -> None:
    asked = _frame("send my exam scripts off to Bram please", "colm").question
    assert asked is not None and "Bram Osei here" in asked


@pytest.mark.parametrize(
    "text",
    [
        "did you send my scripts off to Edexcel?",
        "don't send my scripts off to Edexcel",
        "thanks for sending my scripts off to Edexcel",
        "my scripts were sent off to Edexcel yesterday",
    ],
)
def test_a_question_negation_thanks_or_fact_sends_nothing(text: str) -> None:
    frame = _frame(text, "colm")
    assert frame.tasks == [] and frame.decline is not None


async def test_the_scripts_go_out_to_the_board_named() -> None:
    run = await run_instruction(
        arts_block(), "colm", "my exam scripts need sending off to Edexcel today, can you sort it"
    )
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    [sent] = run.sim.world.sent_out()
    assert sent.detail["item"] == "scripts:colm" and sent.detail["by"] == "marta"
    assert "Edexcel" in sent.detail["told"]
    assert not any(m.chat.id == "edexcel" for m in run.sim.messenger.sent)


@pytest.mark.parametrize(
    "text",
    [
        "Send my tunic to Parkside Cleaners to be dry cleaned please.",
        "Send my costume to Parkside Cleaners to be dry-cleaned please.",
    ],
)
def test_a_two_word_service_named_after_the_place_is_that_service(text: str) -> None:
    frame = InstructionParser(arts_block_dry_cleaning()).parse(text, "hatty")
    assert frame.question is None and frame.decline is None, frame
    assert [(t.operation, t.item, t.destination) for t in frame.tasks] == [
        ("launder", "tunic", "Parkside Cleaners")
    ]


def _arts_block_posting_off() -> InstructionParser:
    """The arts block whose post service is also asked for by "send off" (a verb of two
    words the office declares): a declared phrase in its -ing form is still the verb."""
    raw = raw_arts_block()
    for op in raw["operations"]:
        if op.get("sends_out"):
            op["verbs"] = [*op["verbs"], "send off"]
    return InstructionParser(parse_office(raw, "arts_block"))


@pytest.mark.parametrize(
    ("text", "where"),
    [
        ("my exam scripts need sending off to AQA today, can you sort it", "AQA"),
        ("my Spanish scripts need sending off to Edexcel", "Edexcel"),
        ("can you send my scripts off to AQA today", "AQA"),
    ],
)
def test_a_declared_two_word_send_out_verb_said_with_ing_keeps_its_destination(
    text: str, where: str
) -> None:
    frame = _arts_block_posting_off().parse(text, "colm")
    assert frame.question is None and frame.decline is None, frame
    assert [(t.operation, t.item, t.destination) for t in frame.tasks] == [
        ("post_out", "scripts", where)
    ]
