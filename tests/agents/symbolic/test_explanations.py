"""An explanation beside a request ("... because Rich asked for it", "Rich wants it back
later", "Hal printed his rota yesterday") is context: it neither takes over the recipient nor
adds a task. On a small clinic office none of whose sentences the reader was built on."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic import InstructionParser, Task


@pytest.mark.parametrize(
    "text",
    [
        "print my rota for Hal because Rich asked for it",
        "print my rota for Hal, Rich asked for it",
        "please print my rota for Hal as Rich mentioned it this morning",
        "print the rota for Hal since Dawn is off today",
    ],
)
def test_a_person_in_a_reason_is_not_the_recipient(
    clinic_parser: InstructionParser, text: str
) -> None:
    frame = clinic_parser.parse(text, "ines")
    assert [(t.kind, t.recipient) for t in frame.tasks] == [("print", "hal")], text


def test_a_wish_about_what_was_asked_does_not_take_it_over(
    clinic_parser: InstructionParser,
) -> None:
    frame = clinic_parser.parse("take my form to Hal. Rich wants it back later", "ines")
    assert frame.tasks == [Task(kind="transfer", item="document", owner="ines", recipient="hal")]
    frame = clinic_parser.parse("print my rota, Rich wants it up on the board", "ines")
    assert [t.recipient for t in frame.tasks] == ["ines"]
    # a need for a new thing is still a need: restated and asked
    assert "Rich Adeyemi" in (
        clinic_parser.parse("Rich wants a thermometer", "ines").question or ""
    )


def test_a_task_word_told_as_done_adds_no_task(clinic_parser: InstructionParser) -> None:
    frame = clinic_parser.parse("please print my rota. Hal printed his rota yesterday", "ines")
    assert [(t.kind, t.owner) for t in frame.tasks] == [("print", "ines")]
    frame = clinic_parser.parse("Dawn took my form, could you get me a clipboard?", "ines")
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("transfer", "clipboard", "ines")
    ]
