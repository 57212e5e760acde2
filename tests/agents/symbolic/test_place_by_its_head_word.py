"""A place named by the last word of its name ("take it down to the studio" for the "Imaging
studio") is that place when only it ends so (blind round 63's class: "the studio" was no place,
so "take my deed down to the studio and have it digitised" asked who should get it). Words too
general or meaning something else alone ("the office", "the post"), a letter ("room A") and a
head two places share name no place."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.clipped_names import place_heads
from helpers.imaging_unit import imaging_unit
from helpers.reading import frame_reader

_frame = frame_reader(imaging_unit, "ines")


@pytest.mark.parametrize(
    ("short", "full"),
    [
        (
            "take my letter down to the studio and have it scanned",
            "take my letter down to the imaging studio and have it scanned",
        ),
        (
            "could you bring my letter to the studio and get it digitised?",
            "could you bring my letter to the imaging studio and get it digitised?",
        ),
        ("take my camera to the bay", "take my camera to the loading bay"),
        ("leave my camera in the kitchen", "leave my camera in the staff kitchen"),
    ],
)
def test_the_head_word_reads_as_the_whole_name(short: str, full: str) -> None:
    read = _frame(full).model_dump(exclude={"evidence"})
    if read["question"]:
        # a question quotes the requester's own words ("to the bay"): the rest is the same
        for word in set(full.split()) - set(short.split()):
            read["question"] = read["question"].replace(f"{word} ", "")
    assert _frame(short).model_dump(exclude={"evidence"}) == read


def test_the_work_at_the_studio_is_done() -> None:
    frame = _frame("take my letter down to the studio and have it scanned")
    assert frame.question is None and frame.decline is None, frame
    assert [(t.kind, t.item, t.owner, t.recipient, t.facility) for t in frame.tasks] == [
        ("copy", "letter", "ines", "ines", "scanner")
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        "put my letter in the post",  # the mail, not the security post
        "bring my camera to room A",  # a letter alone names no meeting room
    ],
)
def test_a_word_that_names_no_place_alone_moves_nothing(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is not None, frame


@pytest.mark.parametrize(
    ("names", "taken", "expected"),
    [
        ([("imaging studio", "s")], set(), {"studio": "s"}),
        # two places end in the same word: it names neither
        (
            [("parts store", "p"), ("kit store", "k"), ("imaging studio", "s")],
            set(),
            {"studio": "s"},
        ),
        # a word the office already uses (an item, a person) stays that
        ([("imaging studio", "s")], {"studio"}, {}),
        ([("imaging studio", "s")], {"studios"}, {}),
        # too general, another sense, a letter, a number, a one-word name
        (
            [
                ("main office", "o"),
                ("security post", "p"),
                ("meeting room a", "a"),
                ("bay 2", "b"),
                ("library", "l"),
            ],
            set(),
            {},
        ),
    ],
)
def test_which_heads_name_a_place(
    names: list[tuple[str, str]], taken: set[str], expected: dict[str, str]
) -> None:
    assert place_heads(names, taken) == expected
