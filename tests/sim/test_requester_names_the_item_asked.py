"""The simulated requester asked "Which item do you mean for me to heat or test or shred?"
names the item of the task, never one of the works the question lists (blind round 55's
class; its office and sentences were never read): the works are what was asked, not options,
and "shred" told the reader nothing. A question that really names options is answered by the
option, as before."""

from __future__ import annotations

from assistantx.sim.requester import Wish, answer
from helpers.sample_lab import sample_lab


def _wish() -> Wish:
    return Wish(
        requester="rhea",
        items=("document",),
        own="mine",
        operations=("shred",),
        people=frozenset({"rhea"}),
        whose_items=(("document", "rhea"),),
    )


def test_which_item_is_answered_with_the_item() -> None:
    for question in (
        "Which item do you mean for me to heat or test or shred?",
        "Which item do you mean for me to shred?",
        "What item do you mean: for me to shred or to copy?",
    ):
        said = answer(sample_lab(), _wish(), question)
        assert "document" in said.lower() and "shred" not in said.lower(), (question, said)


def test_a_question_of_options_is_still_answered_by_the_option() -> None:
    said = answer(sample_lab(), _wish(), "Do you mean shred, or heat?")
    assert said == "shred", said
