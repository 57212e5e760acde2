"""An item said in a noun the office does not list, after "my", where the work asked takes one
item type: "Please shred my old medical questionnaire; it's confidential.", shredding taking a
document (blind round 55's class; its office and sentences were never read). The work says
what the thing is, the requester's own document; the noun does not, so the reading is restated
first ("Shall I shred your document for you?"), done on a yes, dropped on a no. The office's
own word ("shred my document") is done as before; a colleague's thing, or a request with no
such work ("bring me my questionnaire"), is not read this way."""

from __future__ import annotations

import pytest

from helpers.reading import answered_reader
from helpers.sample_lab import sample_lab

_answered = answered_reader(sample_lab, "rhea")


@pytest.mark.parametrize(
    "text",
    [
        "Please shred my old medical questionnaire; it's confidential.",
        "shred my questionnaire please",
        "could you shred my old payslip, thanks",
        "can you shred my questionnaire for me",
    ],
)
def test_the_work_names_the_item_and_it_is_restated_first(text: str) -> None:
    asked = _answered(text)
    assert asked.tasks == [] and asked.question == "Shall I shred your document for you?", asked
    done = _answered(text, ["Yes, please."])
    assert [(t.item, t.owner) for t in done.tasks] == [("document", "rhea")], done
    assert done.tasks[0].operation in (None, "shred")
    dropped = _answered(text, ["No, thanks."])
    assert dropped.tasks == [] and dropped.decline is not None, dropped


def test_the_offices_own_word_is_done_without_asking() -> None:
    frame = _answered("shred my document")
    assert frame.question is None and [(t.item, t.owner) for t in frame.tasks] == [
        ("document", "rhea")
    ]


@pytest.mark.parametrize("text", ["bring me my questionnaire", "shred Dana's questionnaire"])
def test_no_guess_without_the_work_or_for_a_colleagues_thing(text: str) -> None:
    frame = _answered(text)
    assert frame.tasks == [] and frame.question is not None, frame
    assert "Shall I" not in frame.question, frame
