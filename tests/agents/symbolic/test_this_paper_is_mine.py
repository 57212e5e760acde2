""" "take this permit to Dr Okafor": the paper at hand, said with "this" or "these", is the
requester's own when they have one, as with "the"; and the answer "Mine." to "Whose document
do you mean?" settles it also where the request said another of the type's names ("a
permit"). Blind round 37's eval class: 4 tasks ended "Your answer 'Mine.' did not tell me"."""

from __future__ import annotations

import pytest

from helpers.port_office import port_office
from helpers.reading import frame_reader, parser_for

_frame = frame_reader(port_office, "tom")


@pytest.mark.parametrize(
    "text",
    [
        "Please take this permit to the Director for me.",
        "take these waivers over to Ada",
        "could you drop this document off with Ada",
    ],
)
def test_this_paper_is_the_requesters_own(text: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "document", "tom", "ada")
    ], frame


def test_this_paper_of_one_who_has_none_is_still_asked() -> None:
    frame = _frame("take this permit to Ada", "kit")
    assert frame.tasks == [] and frame.question == "Whose document do you mean?", frame


@pytest.mark.parametrize("answer", ["Mine.", "it's mine", "my own"])
def test_mine_answers_whose_also_for_another_name_of_the_type(answer: str) -> None:
    parser = parser_for(port_office)
    text = "please bring a permit to Ada"
    assert parser.parse(text, "tom").question == "Whose document do you mean?"
    frame = parser.parse_with_answers(text, "tom", [answer])
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("document", "tom", "ada")]
