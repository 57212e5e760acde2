"""A recipient named by a pronoun as the first of a verb's two objects ("Zhang needs a
stapler for the session, can you sort him one?", "find her one", "get them some") is a person
the requester named: the runtime's guard lets the locker code go to them, so the item
arrives. A person the message never names, or the requester's own "me", gains nothing."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.core.actions import SendQR
from assistantx.runtime.recipients import named_recipients
from helpers.consent_memory import memory
from helpers.dataset_offices import default_office


@pytest.mark.parametrize(
    ("text", "who"),
    [
        ("Zhang needs a stapler for the session, can you sort him one?", "zhang"),
        ("Wang's lost her pen, can you find her one?", "wang"),
        ("Zhang's after scissors for the workshop, could you sort him some?", "zhang"),
        ("Wang needs a stapler. Could you rustle her one up?", "wang"),
        ("Zhang's stapler broke, can you organise him one", "zhang"),
    ],
)
def test_a_pronoun_before_a_second_object_names_its_person(text: str, who: str) -> None:
    assert who in named_recipients(default_office(), memory("lee", text))


@pytest.mark.parametrize(
    "text",
    [
        "can you sort him one?",  # nobody named
        "Zhang needs a stapler, sort me one",  # the requester's own
        "Wang's lost her pen, could you sort one for me?",  # the requester's own
    ],
)
def test_no_one_else_is_named(text: str) -> None:
    found = named_recipients(default_office(), memory("lee", text))
    assert not found, found


async def test_end_to_end_the_item_arrives_and_the_code_goes_to_the_pronouns_person() -> None:
    text = "Zhang needs a stapler for the session, can you sort him one?"
    run = await run_instruction(default_office(), "lee", text)
    trace = run.stm.trace
    sent = [r.action for r in trace.actions() if isinstance(r.action, SendQR) and not r.refused]
    assert any(a.contact == "zhang" and a.purpose == "collect" for a in sent), trace.summary
    assert not any(r.refused for r in trace.actions()), trace.summary
    assert trace.outcome == "done", trace.summary


async def test_end_to_end_a_person_never_named_gets_no_code() -> None:
    text = "can you sort him a stapler?"
    run = await run_instruction(default_office(), "lee", text)
    trace = run.stm.trace
    sent = [r.action for r in trace.actions() if isinstance(r.action, SendQR) and not r.refused]
    assert all(a.contact in {"lee"} or a.purpose != "collect" for a in sent), trace.summary
