"""An initial after a first name two colleagues share (blind rounds 20-22's class, on
``helpers.galley``, an airline catering unit no sentence was written for: Luca Ferrand and
Luca Bianchi): "luca f's costings", "Luca F.'s costings" are Luca Ferrand's, sent to the
requester once Luca Ferrand agrees; "Luca's costings" alone still asks which Luca, and an
initial neither Luca has asks too. The file named again by another of its names ("the
spreadsheet, not a printout") is the same file, not the requester's own to pass on."""

from __future__ import annotations

import pytest
from symbolic_run import run_instruction

from helpers.galley import galley
from helpers.reading import frame_reader

_frame = frame_reader(galley, "nia")


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        ("could you get me luca f's costings", "luca_f"),
        ("get me Luca F.'s costings please", "luca_f"),
        ("get me luca f.'s costings please", "luca_f"),
        ("can you send me luca b's costings", "luca_b"),
        ("send me Luca B.'s costings", "luca_b"),
    ],
)
def test_the_initial_picks_one_luca(text: str, owner: str) -> None:
    frame = _frame(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("send_file", "costings", owner, "nia")
    ]


@pytest.mark.parametrize(
    ("text", "owner"),
    [
        ("could you get me luca f's costings? the spreadsheet, not a printout", "luca_f"),
        ("get me Luca F.'s costings? the spreadsheet, not a printout", "luca_f"),
        ("could you send me Deepa's costings? the spreadsheet", "deepa"),
    ],
)
def test_the_file_named_again_is_the_same_file(text: str, owner: str) -> None:
    frame = _frame(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("send_file", "costings", owner, "nia")
    ]


def test_a_second_file_for_someone_else_is_still_sent() -> None:
    frame = _frame("send me Deepa's costings, and send Holly my costings")
    assert [(t.kind, t.owner, t.recipient) for t in frame.tasks] == [
        ("send_file", "deepa", "nia"),
        ("send_file", "nia", "holly"),
    ]


@pytest.mark.parametrize(
    "text", ["could you get me Luca's costings", "get me luca's costings please"]
)
def test_the_first_name_alone_asks_which(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is not None
    assert "Luca Ferrand" in frame.question and "Luca Bianchi" in frame.question


async def test_luca_ferrand_is_asked_and_the_file_sent_to_the_requester() -> None:
    run = await run_instruction(galley(), "nia", "get me Luca F.'s costings please")
    trace = run.stm.trace
    assert trace.outcome == "done", trace.summary
    asked = [getattr(r.action, "contact", None) for r in trace.actions()]
    assert "luca_f" in asked and "luca_b" not in asked
