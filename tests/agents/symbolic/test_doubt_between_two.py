"""The requester's own doubt between two colleagues ("bring my stapler to Zhang... or was it
Wang?", "give this to Zhang, or maybe Chen, not sure") asks whom, naming both: it was
delivered to the first. The answer that names one of them is who gets it. Where the requester
leaves the choice to the assistant ("Zhang or Chen, whoever's in", "either is fine") one of
them gets it, as before; a plain request to one person is read as before."""

from __future__ import annotations

import functools

import pytest

from assistantx.core.office import Office, load_office
from helpers.dataset_offices import DEFAULT_FILE
from helpers.reading import answered_reader, frame_reader


@functools.cache
def _office() -> Office:
    return load_office(DEFAULT_FILE)


_frame = frame_reader(_office, "lee")
_answered = answered_reader(_office, "lee")


@pytest.mark.parametrize(
    ("text", "names"),
    [
        ("bring my stapler to Zhang... or was it Wang? whoever has the deadline today", "Wang"),
        ("give my stapler to Zhang, or maybe Chen, not sure", "Chen"),
        ("give my stapler to Zhang, or was it Chen?", "Chen"),
        ("bring my stapler to Zhang. Or Chen? I can't remember which", "Chen"),
        ("please take my stapler to Wang or perhaps Zhou, I forget which", "Zhou"),
        ("take my stapler over to Chen, or is it Yang Lei? hmm", "Yang Lei"),
        ("give my stapler to Zhang or Chen", "Chen"),
    ],
)
def test_a_doubt_between_two_people_asks_whom(text: str, names: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is not None, frame
    assert frame.question.startswith("Who should get your stapler:"), frame.question
    assert names in frame.question and " or " in frame.question


@pytest.mark.parametrize(
    ("text", "answer", "recipient"),
    [
        (
            "bring my stapler to Zhang... or was it Wang? whoever has the deadline today",
            "Wang",
            "wang",
        ),
        (
            "bring my stapler to Zhang... or was it Wang? whoever has the deadline today",
            "Zhang Wei.",
            "zhang",
        ),
        ("give my stapler to Zhang, or maybe Chen, not sure", "Chen Jie please", "chen"),
        ("give my stapler to Zhang, or was it Chen?", "It's Zhang", "zhang"),
    ],
)
def test_the_answer_names_who_gets_it(text: str, answer: str, recipient: str) -> None:
    frame = _answered(text, [answer])
    assert [(t.kind, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "lee", recipient)
    ], frame


@pytest.mark.parametrize(
    ("text", "either"),
    [
        ("give my stapler to Zhang or Chen, whoever's in", {"zhang", "chen"}),
        ("give my stapler to Zhang or Chen, either is fine", {"zhang", "chen"}),
        ("take my stapler to Wang or Zhou, whoever is free", {"wang", "zhou"}),
        ("give my stapler to Zhang", {"zhang"}),
        ("give Zhang's stapler to Chen", {"chen"}),
        ("give my stapler to Zhang, not sure when he's back", {"zhang"}),
    ],
)
def test_either_left_to_me_or_one_person_still_delivers(text: str, either: set[str]) -> None:
    frame = _frame(text)
    assert frame.question is None, frame
    assert len(frame.tasks) == 1 and frame.tasks[0].recipient in either, frame


@pytest.mark.parametrize(
    ("text", "kind", "doers"),
    [
        (
            "Could my contract get the approval stamp? Mao or Sun can do it, whoever's free.",
            "seal",
            {"mao", "sun"},
        ),
        ("could this contract of mine get stamped? Mao or Sun could do it", "seal", {"mao", "sun"}),
        ("get my contract stamped by Mao or Sun, whoever is free", "seal", {"mao", "sun"}),
        (
            "can my contract get the stamp? Wang or Mao can do it, either is fine",
            "seal",
            {"wang", "mao"},
        ),
        (
            "Could my contract get signed? Zhang or Chen can do it, whoever's free.",
            "sign",
            {"zhang", "chen"},
        ),
    ],
)
def test_two_people_who_may_do_the_work_are_doers_never_recipients(
    text: str, kind: str, doers: set[str]
) -> None:
    frame = _frame(text)
    assert frame.question is None, frame
    assert [(t.kind, t.owner, t.recipient) for t in frame.tasks] == [(kind, "lee", "lee")], frame
    assert frame.tasks[0].actor in doers


@pytest.mark.parametrize(
    ("text", "kind", "doer", "recipient"),
    [
        ("get my contract stamped by Mao and give it to Sun", "seal", "mao", "sun"),
        ("get my contract signed by Zhang, and then hand it to Chen", "sign", "zhang", "chen"),
        ("get my contract stamped by Mao", "seal", "mao", "lee"),
    ],
)
def test_a_doer_and_a_recipient_named_apart_keep_their_roles(
    text: str, kind: str, doer: str, recipient: str
) -> None:
    frame = _frame(text)
    assert [(t.kind, t.actor, t.recipient) for t in frame.tasks] == [(kind, doer, recipient)], frame
