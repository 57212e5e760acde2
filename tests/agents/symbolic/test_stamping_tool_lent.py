"""The stamping tool lent to a colleague for their own work ("take my seal to Sun Li, she
needs to stamp the agreements") is the tool handed over: it was read as a seal task on the
requester's own document, done by the requester and handed to her. A paper taken to a
colleague to be stamped, or a paper stamped with the tool, is a seal task as before."""

from __future__ import annotations

import functools

import pytest

from assistantx.core.office import Office, load_office
from helpers.dataset_offices import DEFAULT_FILE
from helpers.reading import frame_reader


@functools.cache
def _office() -> Office:
    return load_office(DEFAULT_FILE)


_frame = frame_reader(_office, "mao")


@pytest.mark.parametrize(
    ("text", "who", "owner", "recipient"),
    [
        ("Take my seal to Sun Li, she needs to stamp the agreements", "mao", "mao", "sun"),
        ("Take my seal to Sun Li, she needs to stamp some agreements", "mao", "mao", "sun"),
        ("lend Wang my seal, he needs to stamp his contracts", "mao", "mao", "wang"),
        (
            "could you bring my seal over to Zhang, he needs to stamp the contracts",
            "mao",
            "mao",
            "zhang",
        ),
        ("Take my seal to Sun Li so she can stamp the contracts", "mao", "mao", "sun"),
        ("bring Mao's seal to Sun, she needs to stamp the agreements", "lee", "mao", "sun"),
        ("give my seal to Sun", "mao", "mao", "sun"),
    ],
)
def test_the_tool_lent_to_a_colleague_is_moved(
    text: str, who: str, owner: str, recipient: str
) -> None:
    frame = _frame(text, who)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "seal", owner, recipient)
    ], frame


@pytest.mark.parametrize(
    ("text", "actor", "recipient"),
    [
        ("get my agreement stamped by Sun Li", "sun", "mao"),
        ("take my contract to Sun Li, she needs to stamp it", "sun", "mao"),
        ("take my contract to Sun Li to stamp", "sun", "mao"),
        ("get Sun's seal on my contract", "sun", "mao"),
    ],
)
def test_a_paper_to_be_stamped_is_still_a_seal_task(text: str, actor: str, recipient: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.owner, t.actor, t.recipient) for t in frame.tasks] == [
        ("seal", "mao", actor, recipient)
    ], frame
