"""A pronoun recipient ("lend him mine", "give him Rich's") is the person the message is
about, also when a lender or owner is named beside them or their own item is said to be
broken; a possessive with no item after it ("mine", "Rich's") means the item named before.
On the clinic office."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic import InstructionParser


@pytest.mark.parametrize(
    ("text", "task"),
    [
        ("Hal's clipboard snapped, lend him mine", ("clipboard", "ines", "hal")),
        ("Dawn's thermometer broke, please bring her mine", ("thermometer", "ines", "dawn")),
        ("Tomás needs a clipboard, give him Rich's", ("clipboard", "rich", "tomas")),
        ("Tomás needs a clipboard, give him Rich's clipboard", ("clipboard", "rich", "tomas")),
        ("Hal twisted his ankle, take him May's ice pack", ("ice_pack", "may", "hal")),
    ],
)
def test_the_pronoun_is_the_person_in_need_not_the_lender(
    clinic_parser: InstructionParser, text: str, task: tuple[str, str, str]
) -> None:
    frame = clinic_parser.parse(text, "ines")
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [task], (text, frame)


def test_two_things_asked_for_in_one_breath_stay_two(clinic_parser: InstructionParser) -> None:
    frame = clinic_parser.parse("bring me a clipboard and Rich's clipboard", "ines")
    assert [t.owner for t in frame.tasks] == [None, "rich"]
