"""Three ways an ordinary sentence was misread (blind round 37, after its fixes; the tests'
sentences are their own): a name word counted ("for 5 min") is the word, as after "a"; a
clause that opens with a past verb and its object ("Drew a blank on the rota") drops its "I"
and is the speaker's statement, whoever is called Drew; and "the printer's eaten another
manifest" is "has eaten", a statement, not the printer's manifest."""

from __future__ import annotations

import pytest

from assistantx.core.office import load_office
from helpers.port_office import port_office
from helpers.reading import frame_reader

_default = frame_reader(load_office, "hu")
_port = frame_reader(port_office, "tom")


@pytest.mark.parametrize(
    "text",
    [
        "could I borrow a pair of scissors for 5 min?",
        "can I have some scissors for two min, need to cut labels",
    ],
)
def test_a_counted_name_word_is_the_word(text: str) -> None:
    frame = _default(text)
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("scissors", None, "hu")]


def test_the_name_itself_is_still_the_colleague() -> None:
    frame = _default("give my scissors to Min")
    assert [(t.owner, t.recipient) for t in frame.tasks] == [("hu", "gao")], frame


@pytest.mark.parametrize(
    "text",
    [
        "Drew a blank on the rota again this morning, can't believe it.",
        "Drew the short straw today",
        "Sent the spreadsheet to Ada yesterday",
    ],
)
def test_a_clause_opening_with_a_past_verb_is_the_speakers_statement(text: str) -> None:
    frame = _port(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None


@pytest.mark.parametrize(
    ("text", "recipient"),
    [
        ("Left my radio at home, can you bring me one?", "tom"),
        ("bring the radio to Drew", "drew"),
    ],
)
def test_a_request_beside_it_or_a_plain_verb_reads_as_before(text: str, recipient: str) -> None:
    frame = _port(text)
    assert [(t.item, t.recipient) for t in frame.tasks] == [("radio", recipient)], frame


@pytest.mark.parametrize(
    "text",
    [
        "ugh the printer's eaten another report",
        "the printer's chewed up my report again",
    ],
)
def test_a_contracted_has_before_an_object_is_a_statement(text: str) -> None:
    frame = frame_reader(load_office, "lee")(text)
    assert frame.tasks == [] and frame.question is None, frame


def test_a_possessive_before_an_adjective_still_owns() -> None:
    frame = frame_reader(load_office, "lee")("bring me Zhang's broken stapler")
    assert [(t.item, t.owner) for t in frame.tasks] == [("stapler", "zhang")], frame
