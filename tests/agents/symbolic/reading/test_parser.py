"""The parser runs the stages (tokens, lexicon, screen, readings, frames, judge) on one office and
settles a doubt with the requester's answer by reading again, never by changing itself."""

from __future__ import annotations

from pathlib import Path

from assistantx.agents.symbolic.reading.parser import InstructionParser
from assistantx.core.office import load_office

HARBOUR = Path(__file__).resolve().parents[4] / "dataset" / "offices" / "harbour" / "office.yaml"


def test_a_request_runs_through_every_stage_to_a_frame() -> None:
    p = InstructionParser(load_office())
    frame = p.parse("Wang is away. Bring me a stapeler, please", "lee")
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", "stapler", "lee")]
    assert [h.kind for h in frame.hints] == ["availability"]  # the screen's, handed on


def test_an_answer_settles_a_reading_without_changing_the_parser() -> None:
    p = InstructionParser(load_office(HARBOUR))
    text = "print the flyer for the Grace period talk"
    assert p.parse(text, "may").question is not None
    settled = p.parse_with_answers(text, "may", ["Grace Huang"])
    assert [t.recipient for t in settled.tasks] == ["grace"]
    assert p.lex.chosen == {}
    assert p.parse(text, "may").question is not None  # the next request is read afresh
