"""Blind rounds 20 to 22, class 3: work asked for on an item with no word that says which,
where the office runs two operations on it ("can you do something with my prep before it
turns": vacuum seal or blast chill), is asked about by naming them; the answer names the work.
On sentences of our own against a kitchen no sentence was written for. Nothing moves before
the answer (main brought the prep back to its owner)."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from assistantx.core.task_schema import Part
from helpers.airside_kitchen import airside_kitchen
from helpers.one_episode import ppdr_episode
from helpers.reading import answered_reader, frame_reader

_frame = frame_reader(airside_kitchen, "odile")
_answered = answered_reader(airside_kitchen, "odile")

_ASKED = "Which should I do with your prep: vacuum seal or blast chill?"
_DO_SOMETHING = "can you do something with my prep before it turns"


@pytest.mark.parametrize(
    "text",
    [
        _DO_SOMETHING,
        "can you sort my prep out",
        "deal with my prep please",
        "can you see to my prep before it turns",
        "can you handle my prep",
    ],
)
def test_unsaid_work_on_an_item_two_operations_take_is_asked_by_name(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question == _ASKED


@pytest.mark.parametrize(
    ("answer", "operation"),
    [
        ("vacuum seal", "vac_seal"),
        ("blast chill", "chill"),
        ("the blast chill please", "chill"),
        ("Vacuum seal it, thanks.", "vac_seal"),
    ],
)
def test_the_answer_names_the_work(answer: str, operation: str) -> None:
    frame = _answered(_DO_SOMETHING, [answer])
    assert [(t.operation, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        (operation, "prep", "odile", "odile")
    ]


@pytest.mark.parametrize("answer", ["no idea", "me", "Sorry, I don't know more than I wrote."])
def test_an_answer_that_names_no_work_leaves_it_asked(answer: str) -> None:
    frame = _answered(_DO_SOMETHING, [answer])
    assert frame.tasks == [] and frame.question == _ASKED


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("vac pack my prep", [("vac_seal", "prep")]),
        ("blast chill my prep please", [("chill", "prep")]),
        ("bring Tobin my prep", [(None, "prep")]),
    ],
)
def test_work_or_a_move_said_is_read_as_before(
    text: str, expected: list[tuple[str | None, str]]
) -> None:
    """Near-miss: the work named by its verb, or a move to someone, is no question."""
    assert [(t.operation, t.item) for t in _frame(text).tasks] == expected


def test_bring_me_my_own_item_asks_where_it_is() -> None:
    """Near-miss: "bring me my prep" names a move to the requester, who has it as far as the
    office knows: where it is, not who should get it (fix129e)."""
    assert _frame("bring me my prep").question == (
        "Where is your prep? As far as I know you have it with you."
    )


@pytest.mark.parametrize(
    "text",
    [
        "do something with my trimmings",  # one operation takes them: as before
        "thanks for doing something with my prep",
        "is my prep ok?",
        "don't do anything with my prep",
    ],
)
def test_no_question_of_which_work_where_it_does_not_fit(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question != _ASKED


async def test_nothing_moves_when_the_requester_cannot_say_which() -> None:
    run = await run_instruction(airside_kitchen(), "odile", _DO_SOMETHING)
    asked = [r.action for r in run.stm.trace.actions() if r.action.type == "inquire"]
    assert asked and asked[0].question == _ASKED  # type: ignore[union-attr]
    assert not {"send_qr", "forward_file", "move"} & set(run.actions), run.actions


@pytest.mark.parametrize(("operation", "said"), [("chill", "chilled"), ("vac_seal", "sealed")])
async def test_a_requester_who_knows_which_answers_and_it_is_done(
    operation: str, said: str
) -> None:
    """In evaluation the simulated requester answers the question from the task's truth, and
    the work named is done to their prep."""
    office = airside_kitchen()
    goal: list[dict[str, object]] = [{"heated": "prep:odile"}, {"informed": "odile"}]
    episode = await ppdr_episode(
        office, "odile", _DO_SOMETHING, goal, [Part(kind="heat", operation=operation)]
    )
    asked = [r.action for r in episode.trace.actions() if r.action.type == "inquire"]
    assert [getattr(a, "question", None) for a in asked][:1] == [_ASKED]
    assert episode.trace.outcome == "done", episode.trace.summary
    assert all(episode.milestones) and said in (episode.trace.summary or "")
