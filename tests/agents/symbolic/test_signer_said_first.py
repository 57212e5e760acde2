"""The doer of a person's work said in a first sentence, the request for that work in the
next with no doer ("Zhang Wei has to sign my contract. Can you get it signed and back to
me?"): the statement says who does it, so it is that work by them, the paper back to the
requester. The request alone still asks who; a request naming another doer or another thing
keeps the statement as context."""

from __future__ import annotations

import asyncio

import pytest

from assistantx.core.office import load_office
from assistantx.core.task_spec import BaseInstruction
from assistantx.evaluation.dataset.generate import generate, verify_tasks
from helpers.reading import frame_reader

_frame = frame_reader(load_office, "lee")


@pytest.mark.parametrize(
    ("text", "kind", "actor"),
    [
        (
            "Zhang Wei has to sign my contract. Can you get it signed and back to me?",
            "sign",
            "zhang",
        ),
        ("Zhang has to stamp my form. could you get it stamped?", "seal", "zhang"),
        ("Wang must sign my contract - can you get it signed for me please?", "sign", "wang"),
        (
            "Chen needs to countersign my form. Can you get that signed and back to me?",
            "sign",
            "chen",
        ),
        ("Zhang has to sign my lease, can you sort that", "sign", "zhang"),
        # the work said again with no verb of its own ("get that done", "get it sorted")
        ("Zhang has to sign my contract. Could you get that done?", "sign", "zhang"),
        ("Wang needs to sign my form, can you get it sorted?", "sign", "wang"),
        ("Zhang has to stamp my form. Could you get that done for me?", "seal", "zhang"),
    ],
)
def test_the_doer_said_first_does_the_work_asked_next(text: str, kind: str, actor: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.actor, t.owner, t.recipient) for t in frame.tasks] == [
        (kind, actor, "lee", "lee")
    ], frame


def test_the_request_alone_still_asks_who() -> None:
    frame = _frame("Can you get my contract signed?")
    assert frame.tasks == [] and frame.question is not None and "Who" in frame.question


def test_another_doer_named_in_the_request_is_the_doer() -> None:
    frame = _frame("Zhang has to sign my contract. Can you get it signed by Wang?")
    assert [(t.kind, t.actor) for t in frame.tasks] == [("sign", "wang")], frame


def test_another_thing_asked_for_keeps_the_statement_as_context() -> None:
    frame = _frame("Zhang has to sign my contract. Can you bring me a stapler?")
    assert [(t.kind, t.item) for t in frame.tasks] == [("transfer", "stapler")], frame


def test_the_generator_verifies_a_signer_said_first_then_get_that_done() -> None:
    """The generator's oracle check runs the task through the runtime, whose consent guard
    reads the doer from the same words: it refused Zhang the signing code ("not a party"), so
    ``dataset generate`` failed a valid base instruction."""
    office = load_office()
    base = BaseInstruction.model_validate(
        {
            "id": "b1",
            "requester": "lee",
            "text": "Zhang has to sign my contract. Could you get that done?",
            "parts": [{"kind": "sign", "signer": "zhang"}],
        }
    )
    tasks = [t for t in generate(office, [base], seed=1) if not t.unavailable][:1]
    assert tasks
    asyncio.run(verify_tasks(office, tasks))  # raises where the oracle's run fails
