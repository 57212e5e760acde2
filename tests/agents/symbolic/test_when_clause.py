"""A clause of when run into the command after it with no comma ("when Wang is at the printer
give him my file") is read as with its comma: the clause says when, the command is the
request. Before, the whole was answered as a question about the printer, or asked what was
wanted. A question of when ("when is Wang back?") is still answered."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.when_clause import paused_when_clause
from assistantx.core.office import load_office
from helpers.reading import frame_reader

_lee = frame_reader(load_office, "lee")


@pytest.mark.parametrize(
    ("text", "kind", "item", "owner", "to"),
    [
        ("when Wang is at the printer give him my file", "send_file", "file", "lee", "wang"),
        ("when Wang gets back give him my stapler", "transfer", "stapler", "lee", "wang"),
        ("once Zhang gets back take her my stapler", "transfer", "stapler", "lee", "zhang"),
        ("when Wang needs to print something bring him paper", "transfer", "paper", None, "wang"),
        # must not change: said with the comma
        ("when Wang gets back, give him my stapler", "transfer", "stapler", "lee", "wang"),
    ],
)
def test_the_command_after_a_clause_of_when_is_the_request(
    text: str, kind: str, item: str, owner: str | None, to: str
) -> None:
    frame = _lee(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        (kind, item, owner, to)
    ], frame


def test_a_question_of_when_is_still_answered() -> None:
    frame = _lee("when is Wang back")
    assert frame.tasks == [] and frame.decline is not None, frame
    assert "Desk" in frame.decline, frame


@pytest.mark.parametrize(
    ("text", "read"),
    [
        (
            "when Wang is at the printer give him my file",
            "when Wang is at the printer, give him my file",
        ),
        ("ok. once he's in bring him a pen", "ok. once he's in, bring him a pen"),
        ("when Wang prints it bring it here", "when Wang prints it, bring it here"),
        # no command run in: a noun after its article, a verb after "to", a comma said
        ("when the print run ends", "when the print run ends"),
        ("when Wang needs to print", "when Wang needs to print"),
        ("when Wang is back, give him my file", "when Wang is back, give him my file"),
        ("bring me a pen when Zhang is back", "bring me a pen when Zhang is back"),
    ],
)
def test_the_rewrite(text: str, read: str) -> None:
    assert paused_when_clause(text, {"give", "bring", "print", "prints"}) == read
