"""The parser runs the stages (tokens, lexicon, screen, readings, frames, judge) on one office and
settles a doubt with the requester's answer by reading again, never by changing itself."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.parser import InstructionParser, shared_parser
from assistantx.agents.symbolic.requests import RequestRecognizer
from assistantx.core.office import load_office
from helpers.added_kinds import kind_added, signing_kind
from helpers.dataset_offices import HARBOUR_FILE as HARBOUR


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


def test_the_office_readers_share_one_parser_rebuilt_when_the_kinds_change() -> None:
    office, other = load_office(), load_office(HARBOUR)
    shared = shared_parser(office)
    assert shared_parser(office) is shared
    assert shared_parser(other) is not shared
    assert RequestRecognizer(office)._parser is shared  # the service's request check
    approve = signing_kind(
        "approve_shared",
        "approve",
        "approved",
        "approver",
        words=("endorse",),
        milestone="approved_shared",
    )
    with kind_added(approve):
        rebuilt = shared_parser(office)  # reads the new kind's words
        assert rebuilt is not shared
        assert "endorse" in rebuilt.lex.cue_words and "endorse" not in shared.lex.cue_words


def test_the_shared_parser_remembers_what_it_read_and_reads_it_alike() -> None:
    office = load_office(HARBOUR)
    shared = shared_parser(office)
    text = "print the flyer for the Grace period talk"
    asked = shared.parse_with_answers(text, "may", [])
    assert shared.parse_with_answers(text, "may", []) is asked  # not read again
    settled = shared.parse_with_answers(text, "may", ["Grace Huang"])
    assert settled is not asked and [t.recipient for t in settled.tasks] == ["grace"]
    fresh = InstructionParser(office)  # a parser of its own reads afresh each time
    assert fresh.parse_with_answers(text, "may", []) == asked
    assert fresh.parse_with_answers(text, "may", []) is not fresh.parse_with_answers(
        text, "may", []
    )


def test_one_errand_said_twice_on_ones_own_thing_is_one_task() -> None:
    """ "take my lunch to the microwave. it needs heating": the room's work and the need each
    read as the task, and the lunch was to be heated twice."""
    p = InstructionParser(load_office())
    rows = [
        (t.kind, t.item, t.owner, t.recipient)
        for t in p.parse("take my lunch to the microwave. it needs heating", "lee").tasks
    ]
    assert rows == [("heat", "lunch", "lee", "lee")]
    twice = p.parse("heat my lunch and heat my lunch", "lee").tasks
    assert len(twice) == 1
    # things made for anyone are left as said: one for each recipient
    coffees = p.parse("bring me a coffee and a coffee for Wang", "lee").tasks
    assert [t.recipient for t in coffees] == ["lee", "wang"]
