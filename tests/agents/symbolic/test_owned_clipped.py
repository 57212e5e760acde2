"""A clipped or misspelt word after "my"/"our" that fits several item types names the one the
speaker owns ("my batt" of a camera battery, where the office keeps AA batteries called
"batts"); where the speaker owns none of them, the service asked for breaks the tie (round
166, class 5; ``screen.owned_clipped``). Without "my", or said as the office's own word, the
lexicon's reading stands."""

from __future__ import annotations

import pytest
from _offices import tasks_of

from assistantx.agents.symbolic import InstructionParser
from assistantx.agents.symbolic.reading.screen.owned_clipped import owned_clipped
from assistantx.core.task_schema import TaskFrame
from helpers.kit_room import kit_room
from helpers.reading import frame_reader

_ana = frame_reader(kit_room, "ana")  # owns a camera battery and a lapel microphone
_dev = frame_reader(kit_room, "dev")  # owns neither


def _tasks(frame: TaskFrame) -> list[tuple[str, str | None, str | None, str, str | None]]:
    return [(t.kind, t.item, t.owner, t.recipient, t.operation) for t in frame.tasks]


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        # the class's analogue
        (
            "my batt's flat, can you get it charged at the kit counter",
            ("heat", "camera_battery", "ana", "ana", "charge"),
        ),
        # variants: the service's verb asked, another clipped word, another errand
        ("can you charge my batt", ("heat", "camera_battery", "ana", "ana", "charge")),
        ("my batt is dead, charge it pls", ("heat", "camera_battery", "ana", "ana", "charge")),
        ("can you bring my mic to Sam", ("transfer", "lav_mic", "ana", "sam", None)),
    ],
)
def test_the_speakers_own_type_wins(
    text: str, expected: tuple[str, str, str, str, str | None]
) -> None:
    frame = _ana(text)
    assert _tasks(frame) == [expected], frame


def test_the_service_breaks_the_tie_where_the_speaker_owns_none() -> None:
    # Devika owns no battery: "charge" works on the camera battery only
    frame = _dev("can you charge my batt")
    assert _tasks(frame) == [("heat", "camera_battery", "dev", "dev", "charge")], frame


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        # no "my": anyone's, the office's own word
        ("bring me some batts", ("transfer", "aa_batteries", None, "ana", None)),
        ("bring me a mic", ("transfer", "spare_mics", None, "ana", None)),
    ],
)
def test_without_my_the_lexicons_reading_stands(
    text: str, expected: tuple[str, str | None, str | None, str, None]
) -> None:
    frame = _ana(text)
    assert _tasks(frame) == [expected], frame


@pytest.mark.parametrize("text", ["bring my charg to Mark", "can you take my charg over to Mark"])
def test_the_same_on_harbour(text: str) -> None:
    # harbour's "char" is tea; Bill owns a laptop charger, which "charg" clips
    assert tasks_of("harbour", text, "bill") == [("transfer", "charger", "bill", "mark")]


def test_an_office_word_said_short_is_read_as_it_is() -> None:
    # "calc" is the calculator's own synonym: no clipping read, though it clips "calculator"
    assert tasks_of("harbour", "bring my calc to Mark", "bill") == [
        ("transfer", "calculator", "bill", "mark")
    ]


@pytest.mark.parametrize(
    "text",
    [
        "need my batt pack charged",  # the thing is the pack: "batt" only says which
        "courier my customs declaration asap",
        "get my cert translation stamped",
    ],
)
def test_a_word_said_before_a_noun_of_its_own_phrase_is_left_as_said(text: str) -> None:
    """ "my cert translation stamped" (a blind round's office, where "cert" clipped two types)
    was rewritten to the speaker's own type and the stamping lost: a word that modifies a noun
    after it is no clipped thing."""
    terms = InstructionParser(kit_room()).screen.terms
    assert owned_clipped(terms, text, "ana") == (text, [])
