"""A need put off till later is not a request to move now (``reading.future_need``,
``screen.others_future_need``): the future tense of the need verb ("I'll need", "gonna need",
"we're going to need") or a time after now in the need's own clause ("later", "tomorrow
morning", "after lunch", "at 3", "for the meeting later") is answered in words, and a
colleague's future need is restated and asked ("Shall I bring a calculator to Mark?"), never
fetched at once. With a request beside it ("..., can you bring me one?", "bring it now") or
"now" in its words, it is delivered as before. On the dataset's default office and harbour."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.core.task_schema import TaskFrame
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_harbour = frame_reader(harbour_office, "pat")
_default = frame_reader(default_office, "zhang")


def _read(office: str, text: str) -> TaskFrame:
    return (_harbour if office == "harbour" else _default)(text)


def _tasks(frame: TaskFrame) -> list[tuple[str, str | None, str | None]]:
    return [(t.kind, t.item, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    ("office", "text"),
    [
        # the class's analogues
        ("harbour", "gonna need a ruler later for the workshop"),
        ("default", "I'll need scissors tomorrow morning"),
        # variants of our own: other future forms, other times, other things
        ("harbour", "we're going to need the calculator for the meeting later"),
        ("harbour", "I'm going to need a highlighter"),
        ("harbour", "I will probably need an umbrella"),
        ("harbour", "I need a notepad at 3"),
        ("default", "need a stapler this afternoon for the review"),
        ("default", "I'll need the stapler after lunch"),
        ("default", "gonna need scissors"),
    ],
)
def test_the_speakers_need_for_later_is_answered_not_fetched(office: str, text: str) -> None:
    frame = _read(office, text)
    assert frame.tasks == [], _tasks(frame)
    assert frame.question is None, frame.question
    assert frame.decline is not None and frame.decline_outcome == "done", frame.decline


@pytest.mark.parametrize(
    ("office", "text", "item", "person"),
    [
        ("harbour", "Mark's going to need the calculator after lunch", "calculator", "mark"),
        ("harbour", "Grace'll need a ruler at 3", "ruler", "grace"),
        ("harbour", "Will is gonna need the umbrella tomorrow", "umbrella", "will"),
        ("default", "Lee will need a stapler for the meeting later", "stapler", "lee"),
        ("default", "Wang Fang's going to need scissors this afternoon", "scissors", "wang"),
        # a name that is also the modal "will", before a third person's "needs": the subject
        ("harbour", "Will needs the umbrella", "umbrella", "will"),
    ],
)
def test_a_colleagues_need_for_later_is_asked_before_anything_moves(
    office: str, text: str, item: str, person: str
) -> None:
    """Not the speaker's need, and "Mark's" is no owner: the colleague's need is restated."""
    frame = _read(office, text)
    assert frame.question is not None and frame.question.startswith("Shall I"), frame.question
    assert _tasks(frame) in ([], [("transfer", item, person)])


@pytest.mark.parametrize(
    ("office", "text", "item", "person"),
    [
        # the class's neighbours: asked for now, beside the need or in its words
        ("harbour", "I'm going to need a ruler, can you bring me one?", "ruler", "pat"),
        ("harbour", "need a ruler for the workshop later, bring it now pls", "ruler", "pat"),
        ("harbour", "Mark's going to need the calculator, take it to him", "calculator", "mark"),
        ("harbour", "gonna need a highlighter, bring it now", "highlighter", "pat"),
        ("default", "Lee will need a stapler, please bring him one", "stapler", "lee"),
        ("default", "I need a stapler now for the meeting later", "stapler", "zhang"),
        ("default", "I need a stapler by tomorrow", "stapler", "zhang"),
        # a time in a deadline's clause ("before ... at 4") says by when, not that it can wait
        ("default", "need a stapler before the courier leaves at 4", "stapler", "zhang"),
        ("harbour", "I need a ruler before the meeting this afternoon", "ruler", "pat"),
        ("harbour", "need a highlighter until the workshop ends at 5", "highlighter", "pat"),
        # a time of the event the thing is for: needed before it, so asked for now
        ("default", "I need Wang's stapler for a consult at 3", "stapler", "zhang"),
        ("harbour", "need a ruler for the meeting at 2", "ruler", "pat"),
        # a time said in another clause than the need's: the need is now
        ("default", "I need a stapler and I'll give it back later", "stapler", "zhang"),
        ("default", "I need a stapler", "stapler", "zhang"),
        # the assistant asked in so many words, whatever the tense
        ("harbour", "I'm going to need you to bring me a ruler", "ruler", "pat"),
        ("default", "I'll need you to get me a stapler", "stapler", "zhang"),
    ],
)
def test_a_need_asked_for_now_is_still_delivered(
    office: str, text: str, item: str, person: str
) -> None:
    frame = _read(office, text)
    assert frame.question is None and frame.decline is None, (frame.question, frame.decline)
    assert _tasks(frame) == [("transfer", item, person)]


def test_a_signature_needed_before_a_deadline_is_asked_for_now() -> None:
    """ "need Dr Wang's signature on my document before the truck leaves at 4": the time is
    the deadline's, so the signature is a request of now (blind round 72 after fix74c)."""
    frame = _read("default", "need Dr Wang's signature on my document before the truck leaves at 4")
    assert frame.question is None and frame.decline is None, (frame.question, frame.decline)
    assert [(t.kind, t.actor) for t in frame.tasks] == [("sign", "wang")]


def test_a_things_future_need_is_no_colleagues() -> None:
    """ "my stapler is going to need a refill": said of a thing, never a person's need."""
    frame = _read("default", "my stapler is going to need a refill")
    assert frame.tasks == [] and frame.question is None


async def test_a_need_for_later_moves_nothing_in_the_simulated_office() -> None:
    run = await run_instruction(
        harbour_office(), "pat", "gonna need a ruler later for the workshop"
    )
    assert run.actions == ["stop"], run.actions
    assert run.stm.trace.outcome == "done"
