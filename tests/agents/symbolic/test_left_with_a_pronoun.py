"""A thing left with a person goes to them: "drop it with her", "leave it with him", "drop it
off with her" name as recipient the one colleague said before, as "leave it with Zhang" names
Zhang (fix154a class 4: "Eilidh needs the stats ..., can you print my spreadsheet and drop it
with her" handed the printout to the speaker, a wrong physical action). A "with" after no
verb of leaving ("go through it with her") hands nothing over, and "drop it on my desk" is
still the speaker's."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader

_default = frame_reader(default_office, "lee")
_harbour = frame_reader(harbour_office, "rose")


@pytest.mark.parametrize(
    ("text", "whom"),
    [
        ("Wang needs the figures, can you print my file and drop it with him", "wang"),
        ("Wang needs the figures, can you print my file and drop it with her", "wang"),
        ("Zhang wants the numbers, print my report and drop it off with him", "zhang"),
        ("Chen's presenting at 2, print my file and leave the printout with him", "chen"),
        ("print my report and leave it with Zhang", "zhang"),
    ],
)
def test_a_printout_left_with_someone_is_theirs_in_the_default_office(text: str, whom: str) -> None:
    frame = _default(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("print", "file", "lee", whom)
    ]


@pytest.mark.parametrize(
    ("text", "whom"),
    [
        (
            "Grace needs the stats for the station meeting, can you print my spreadsheet and "
            "drop it with her",
            "grace",
        ),
        ("Mark wants the numbers, print my file and leave it with him", "mark"),
    ],
)
def test_a_printout_left_with_someone_is_theirs_in_harbour(text: str, whom: str) -> None:
    frame = _harbour(text)
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("print", "file", whom)]


def test_a_thing_of_mine_left_with_her_is_handed_to_her() -> None:
    frame = _default("Wang needs my stapler, can you drop it with her")
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "stapler", "lee", "wang")
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        "print my file and drop it with her",  # nobody named: asked, never the speaker
        "Wang and Zhang need the figures, print my file and drop it with her",  # two named
    ],
)
def test_her_of_nobody_or_of_two_is_asked(text: str) -> None:
    frame = _default(text)
    assert frame.tasks == [] and frame.question is not None and "'her'" in frame.question


@pytest.mark.parametrize(
    "text",
    [
        "print my report and drop it on my desk",
        "Wang needs the figures, print my file and go through it with her",
    ],
)
def test_no_leaving_with_someone_keeps_the_speaker_as_recipient(text: str) -> None:
    frame = _default(text)
    assert [(t.kind, t.recipient) for t in frame.tasks] == [("print", "lee")], frame
