"""Months and weekdays are dates, not people (from the standard library's calendar, not a
hand-written list); a month that is also a colleague's name is the person only where the
syntax says so, and where both readings fit and lead to different hand-overs, one short
question names both. On the clinic office, where May Oduya works."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic import InstructionParser


@pytest.mark.parametrize(
    "text",
    [
        "print the rota for May 3rd",
        "print my rota for the 3rd of May",
        "print my rota for March and April",
        "print my rota, it is due in May",
    ],
)
def test_a_date_is_not_a_person(clinic_parser: InstructionParser, text: str) -> None:
    frame = clinic_parser.parse(text, "ines")
    assert [(t.kind, t.recipient) for t in frame.tasks] == [("print", "ines")], (text, frame)


def test_a_weekday_or_month_nobody_is_called_is_never_asked_about(
    clinic_parser: InstructionParser,
) -> None:
    frame = clinic_parser.parse("bring the clipboard to May by Friday", "ines")
    assert [(t.item, t.recipient) for t in frame.tasks] == [("clipboard", "may")]
    for text in ("bring me Dawn's form from March", "bring me Hal's form by Friday"):
        frame = clinic_parser.parse(text, "ines")
        assert "anyone called" not in (frame.question or ""), text
        assert len(frame.tasks) == 1, text


def test_for_a_month_that_is_a_name_asks_which_and_the_answer_settles_it(
    clinic_parser: InstructionParser,
) -> None:
    text = "print the rota for May"
    assert (
        clinic_parser.parse(text, "ines").question == "Do you mean May Oduya, or the month of May?"
    )
    month = clinic_parser.parse_with_answers(text, "ines", ["the month"])
    assert [t.recipient for t in month.tasks] == ["ines"]
    her = clinic_parser.parse_with_answers(text, "ines", ["May Oduya"])
    assert [t.recipient for t in her.tasks] == ["may"]
    # "to May" and "May's" are the person
    assert [t.recipient for t in clinic_parser.parse("take my form to May", "ines").tasks] == [
        "may"
    ]
