"""A name that is an ordinary word, made the doer by "get/have/want ... (to) <verb>" (blind
rounds 20-22's class, on ``helpers.galley``, an airline catering unit no sentence was written
for): "can you get holly to sign this release form?" asks Holly to sign, the form comes back
to the requester; "the chef's agent wants it back" is a reason, not Chef Ramón. "get holly
to the bag room", "some holly for the tables" make no doer; a question, a thanks or a "don't"
still moves nothing. The consent guard reads the name as the reader does
(``core.name_reading``), so the signature is asked of Holly, never refused."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.core.name_reading import NameSlot, read_name
from helpers.galley import galley
from helpers.reading import frame_reader

_frame = frame_reader(galley, "nia")


@pytest.mark.parametrize(
    "text",
    [
        "can you get holly to sign this release form? the chef's agent wants it back before "
        "the cooking slot",
        "get holly to sign my release form",
        "could you get holly to sign my release form, the chef's agent needs it back",
        "have holly sign my release form, the chef wants it by noon",
        "could you have holly sign my release form",
        "pls have holly sign my release form",
        "I need holly to sign my release form before the cooking slot",
    ],
)
def test_holly_signs_and_the_form_comes_back(text: str) -> None:
    frame = _frame(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient, t.actor) for t in frame.tasks] == [
        ("sign", "release_form", "nia", "nia", "holly")
    ]


@pytest.mark.parametrize(
    "text",
    [
        "is holly signing my release form?",
        "thanks for getting holly to sign my release form",
        "don't get holly to sign my release form",
        "pls has Holly signed my release form",
        "pls is the stapler here",
        "pls are there any staplers left",
    ],
)
def test_no_request_moves_nothing(text: str) -> None:
    assert _frame(text).tasks == []


@pytest.mark.parametrize("text", ["get holly to the bag room", "get me some holly for the tables"])
def test_no_verb_after_the_name_makes_no_doer(text: str) -> None:
    frame = _frame(text)
    assert not any(t.actor == "holly" or t.recipient == "holly" for t in frame.tasks), frame


@pytest.mark.parametrize(
    ("prev", "nxt", "after_next", "reading"),
    [
        ("get", "to", "sign", "person"),
        ("want", "to", "check", "person"),
        ("have", "sign", "my", "person"),
        ("get", "to", "the", "word"),
        ("some", "for", "the", "word"),
        ("have", "leaves", "on", "word"),
    ],
)
def test_the_doer_is_read_alike_by_reader_and_guard(
    prev: str, nxt: str, after_next: str, reading: str
) -> None:
    slot = NameSlot("holly", "holly", prev=prev, next=nxt, after_next=after_next)
    assert read_name(slot) == reading


async def test_holly_is_asked_to_sign_and_the_form_returns() -> None:
    text = (
        "can you get holly to sign this release form? the chef's agent wants it back before "
        "the cooking slot"
    )
    run = await run_instruction(galley(), "nia", text)
    trace = run.stm.trace
    assert trace.outcome == "done", trace.summary
    refused = [r.action for r in trace.actions() if r.refused]
    assert refused == []
    asked = {getattr(r.action, "contact", None) for r in trace.actions()}
    assert "ramon" not in asked
