"""A colleague's obligation to do a person's work (sign, stamp, approve ...) on the speaker's
thing, said as a statement with the thing only as "it" after the sentence that names it ("I've
got the incident form from today. Wang has to sign it before it goes to HR."), implies the
errand: restated and asked ("Shall I get your document signed by Wang Fang?"), never done
unasked and never dropped as "Noted" (``reading.speech``: ``SpeechActs.need``). "has to", "must",
"should" read as "needs to" already did."""

from __future__ import annotations

import pytest
from _offices import parser, tasks_of


@pytest.mark.parametrize(
    "text",
    [
        "I've got the incident form from today. Wang has to sign it before it goes to HR.",
        "I've got my form here. Wang must sign it.",
        "my form is finished. Wang should sign it before Friday",
        # must not change: said with "needs to"
        "I have the incident form. Wang needs to sign it.",
    ],
)
def test_the_obligation_on_it_is_restated_and_asked(text: str) -> None:
    frame = parser("default").parse(text, "lee")
    assert frame.tasks == [], frame
    assert frame.question is not None and "Wang Fang" in frame.question, frame.question
    done = parser("default").parse_with_answers(text, "lee", ["yes"])
    assert [(t.kind, t.owner, t.actor) for t in done.tasks] == [("sign", "lee", "wang")], done


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        # must not change: told as past, or done already, is told; "my form" is asked for
        ("I've got my form. Wang had to sign it.", []),
        ("I've got my form. Wang has signed it.", []),
        ("Wang has to sign my form", [("sign", "document", "lee", "lee")]),
    ],
)
def test_what_is_told_or_asked_reads_as_before(text: str, expected: list[object]) -> None:
    assert tasks_of("default", text, "lee") == expected
