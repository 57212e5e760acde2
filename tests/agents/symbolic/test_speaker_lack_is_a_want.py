"""The speaker's own lack of a thing, said to the assistant, is a want of it for the speaker
("I've run out of wipes and have ten desks to clean", "I've got 40 forms to sign and no
pen": read as a statement, "Noted. I did nothing.", or asked about the forms). The lack
phrases are the language data's (``speaker_lack_phrases``); the work in hand beside the lack
("ten desks to clean", "40 forms to sign") is why the thing is wanted, never a thing to act
on (``reading.work_in_hand``). A facility's lack, a colleague's, a thing said not to be
needed, a lack said of home and a lack beside a request for something else keep their
readings."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import OfficeOf, frame_reader

_WHO = {default_office: "lee", harbour_office: "will"}


def _tasks(office: OfficeOf, text: str) -> list[tuple[str, str | None, str | None]]:
    frame = frame_reader(office, _WHO[office])(text)
    assert frame.question is None and frame.decline is None, frame
    return [(t.kind, t.item, t.recipient) for t in frame.tasks]


@pytest.mark.parametrize(
    ("office", "text", "item"),
    [
        # the class's analogues
        (default_office, "I've run out of wipes and have ten desks to clean.", "wipes"),
        (default_office, "I've got 40 forms to sign and no pen", "pen"),
        # the lack said alone, in each of its phrasings
        (default_office, "I'm out of paper", "paper"),
        (default_office, "I have no pen", "pen"),
        (default_office, "no wipes left and the kitchen is a mess", "wipes"),
        (harbour_office, "I'm out of highlighters", "highlighter"),
        (harbour_office, "we're out of tape", "tape"),
        (harbour_office, "I have no tape", "tape"),
        # with the work in hand before or after it
        (default_office, "I have no stapler and 30 reports to bind", "stapler"),
        (default_office, "I've run out of paper and have a report to print", "paper"),
        (default_office, "I've got 5 reports to staple and no stapler", "stapler"),
        (default_office, "got a pile of forms to sign and no pen, ugh", "pen"),
        (harbour_office, "I've run out of tape and have six parcels to wrap", "tape"),
        (harbour_office, "I've got six parcels to wrap and no tape", "tape"),
        # "to mark up" where Mark works: the work, never a recipient
        (
            harbour_office,
            "I've run out of highlighters and have 20 pages to mark up",
            "highlighter",
        ),
    ],
)
def test_the_speakers_lack_is_a_want_for_them(office: OfficeOf, text: str, item: str) -> None:
    assert _tasks(office, text) == [("transfer", item, _WHO[office])]


def test_a_lack_of_what_a_machine_makes_is_made_for_the_speaker() -> None:
    tasks = _tasks(harbour_office, "got a stack of letters to post and no stamps")
    assert tasks == [("produce", "stamped_envelope", "will")]


@pytest.mark.parametrize(
    "text",
    [
        "the printer has run out of paper",  # a facility's state: words
        "Wang has no pen",  # a colleague's lack: words
        "no pen needed, thanks",  # not wanted at all
        "no stapler required",
        "I've run out of pens at home, I'll pick some up tonight",  # their own plan
        "I have no idea",  # no thing of the office
        "I'm out of the office today",
        # one's own lunch, paper or file is nobody's to bring: news, as before
        "I have no lunch today",
        "I have no document",
    ],
)
def test_no_lack_of_the_speakers_moves_nothing(text: str) -> None:
    frame = frame_reader(default_office, "lee")(text)
    assert frame.tasks == [] and frame.question is None, frame


@pytest.mark.parametrize(
    ("text", "item"),
    [
        ("I ran out of paper. Could you bring me a pen?", "pen"),  # the lack is the reason
        ("I'm out of paper, can you find me some?", "paper"),  # one paper, not two
    ],
)
def test_a_lack_beside_a_request_is_its_reason(text: str, item: str) -> None:
    assert _tasks(default_office, text) == [("transfer", item, "lee")]
