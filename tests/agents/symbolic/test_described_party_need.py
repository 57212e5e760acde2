"""A need said of someone described by a noun that names nothing of the office ("the carver
needs a stapler") is theirs, not the speaker's: it is told, and met with "Shall I ...?"
before anything moves (``speech.SpeechActs.need``); once a later "him" is named ("could you
take him mine" → "Zhang Wei."), that one hand-over meets it and nothing is fetched for the
speaker as well (``needs_met``: it had made two hand-overs, one of someone's stapler to the
speaker). A workstation's occupant described by a word that only describes one of the
office's things ("the mason on bench 3", where a "mason's square" is a thing) is still that
colleague (``seated_subject``). On the default office and a small office (helpers.dive_van)."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.parser import InstructionParser
from assistantx.runtime.recipients import named_recipients
from helpers.consent_memory import memory
from helpers.dataset_offices import default_office
from helpers.dive_van import raw_dive_van
from helpers.office_builder import Row, parsed
from helpers.reading import frame_reader

_default = frame_reader(default_office, "lee")


@pytest.mark.parametrize(
    "text",
    ["the carver needs a stapler", "a new lad needs a stapler", "the carver needs a stapler."],
)
def test_a_described_persons_need_is_asked_before_anything_moves(text: str) -> None:
    frame = _default(text)
    assert frame.tasks == [], frame
    assert frame.question == "Shall I bring a stapler to you?", frame


@pytest.mark.parametrize(
    "text",
    [
        "the carver needs a stapler, could you take him mine",
        "the carver needs a stapler. could you bring him mine",
    ],
)
def test_the_hand_over_to_the_one_named_meets_the_need(text: str) -> None:
    parser = InstructionParser(default_office())
    asked = parser.parse(text, "lee")
    assert asked.tasks == [] and asked.question is not None, asked
    frame = parser.parse_with_answers(text, "lee", ["Zhang Wei."])
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("stapler", "lee", "zhang")]


@pytest.mark.parametrize(
    ("text", "moves"),
    [
        # must not change: the speaker's own thing, an office thing, the speaker's need
        ("my laptop needs a data cable", [("data_cable", None, "lee")]),
        ("the printer needs paper. bring me some", [("paper", None, "lee")]),
        ("I need a stapler", [("stapler", None, "lee")]),
    ],
)
def test_the_speakers_own_needs_are_unchanged(
    text: str, moves: list[tuple[str, str | None, str]]
) -> None:
    frame = _default(text)
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == moves, frame


def _with_masons_square() -> Row:
    raw = raw_dive_van()
    for t in raw["item_types"]:
        if t["id"] == "set_square":
            t["synonyms"] = ["square", "mason's square", "mason square"]
    return raw


def test_a_word_describing_a_thing_still_describes_the_seated_colleague() -> None:
    van = frame_reader(parsed(_with_masons_square), "lee")
    frame = van("the mason on bench 3 needs a set square. could you bring him mine")
    assert frame.question is None, frame
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("set_square", "lee", "eoin")
    ], frame


def test_the_consent_guard_reads_the_seated_colleague_as_the_reader_does() -> None:
    # the code for Eoin's set square may go to Eoin: the guard names him as the reader does
    said = "the mason on bench 3 needs a set square. could you bring him mine"
    assert "eoin" in named_recipients(parsed(_with_masons_square)(), memory("lee", said))
