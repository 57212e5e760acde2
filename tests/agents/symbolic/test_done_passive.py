"""Work reported done in the present-perfect passive ("they've just been sharpened", "it has
already been signed") is told, never asked: beside a wish to leave the thing alone nothing
moves and no service runs (round 166, class 1; ``reading.done_passive``). The same service
asked for in the passive, needed, or asked after a report of something else still runs."""

from __future__ import annotations

import pytest
from _offices import parser, tasks_of

from helpers.kit_room import kit_room
from helpers.reading import frame_reader

_kit = frame_reader(kit_room, "ana")


@pytest.mark.parametrize(
    "text",
    [
        # the class's analogues
        "nobody touch my clippers, they've just been sharpened",
        "don't move my folder, it's been signed already",
        "leave my badge alone pls, it has just been laminated",
        # variants: another service's verb, the pronoun joined, a noun subject, no adverb
        "hands off my clippers, they've been honed",
        "nobody touch my clippers, theyve already been sharpened",
        "no one take my camera card, it's just been ingested",
        "leave my battery pack alone, it has been charged",
        "my clippers've just been sharpened so leave them be",
    ],
)
def test_done_work_beside_a_wish_moves_nothing(text: str) -> None:
    frame = _kit(text)
    assert frame.tasks == [], frame


@pytest.mark.parametrize(
    ("office", "requester", "text"),
    [
        ("harbour", "bill", "no one move my badge, they've been laminated"),
        ("harbour", "bill", "nobody touch my document, it has already been scanned"),
        ("default", "lee", "nobody touch my lunch pls, it's already been warmed"),
        ("default", "lee", "leave my document alone, they've just been copied"),
    ],
)
def test_the_same_on_the_dataset_offices(office: str, requester: str, text: str) -> None:
    assert tasks_of(office, text, requester) == []


@pytest.mark.parametrize(
    ("text", "operation"),
    [
        ("can my clippers be sharpened?", "sharpen"),  # asked in the passive
        ("my clippers need sharpening", "sharpen"),  # a need
        ("nobody's used the sharpener, can you sharpen my clippers", "sharpen"),  # asked after
        ("my badge has been dropped, could you laminate it", "laminate"),  # asked after
    ],
)
def test_the_service_asked_still_runs(text: str, operation: str) -> None:
    frame = _kit(text)
    assert [(t.item, t.owner, t.operation) for t in frame.tasks] == [
        (text.split("my ")[1].split()[0], "ana", operation)
    ], frame


def test_a_question_about_the_done_work_is_still_a_question() -> None:
    # the auxiliary first: asked about, answered in words (harbour's laminator)
    assert parser("harbour").parse("has my badge been laminated yet?", "bill").tasks == []
