"""The last stage: the screen's own reply, or the frames judged with its hints and evidence."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.findings import Screened
from assistantx.agents.symbolic.reading.screen.judge import answered_frame, judge, task_evidence
from assistantx.core.office import Office
from assistantx.core.task_schema import Hint, Task, TaskFrame

_AWAY = Hint(kind="availability", person="wang", value="away", said="Wang is away")


def test_a_message_the_screen_answered_ends_with_its_reply() -> None:
    screened = Screened(text="", decline="You're welcome! I did nothing.", outcome="done")
    frame = answered_frame(screened, "lee")
    assert (frame.decline, frame.decline_outcome, frame.tasks) == (
        "You're welcome! I did nothing.",
        "done",
        [],
    )
    asked = answered_frame(Screened(text="", question="Shall I bring you one?"), "lee")
    assert asked.question == "Shall I bring you one?"


def _fetch() -> TaskFrame:
    return TaskFrame(requester="lee", tasks=[Task(kind="transfer", item="pen", recipient="gao")])


def test_the_frames_get_the_screens_hints_and_a_task_in_words(office: Office) -> None:
    screened = Screened(text="bring Gao a pen ", hints=[_AWAY])
    frame = judge(office, screened, _fetch(), "lee", confirmed=False)
    assert frame.hints == [_AWAY]
    assert [(e.words, e.meaning) for e in frame.evidence] == [
        ("bring Gao a pen", "transfer: anyone's pen for Gao Min")
    ]


def test_a_need_to_restate_is_asked_before_anything_moves(office: Office) -> None:
    screened = Screened(text="Gao needs a pen", confirm=True)
    frame = judge(office, screened, _fetch(), "lee", confirmed=False)
    assert frame.tasks == [] and frame.question is not None
    assert frame.question.startswith("Shall I ")
    confirmed = judge(office, screened, _fetch(), "lee", confirmed=True)
    assert len(confirmed.tasks) == 1


def test_a_task_in_words_names_whose_item_and_by_whom(office: Office) -> None:
    task = Task(kind="transfer", item="stapler", owner="wang", actor="zhang", recipient="lee")
    said = task_evidence(office, task, "x" * 400)
    assert said.meaning == "transfer: Wang Fang's stapler by Zhang Wei for Lee Ming"
    assert len(said.words) == 300
