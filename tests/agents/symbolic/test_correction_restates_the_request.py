"""A correction ("no wait", "sorry, I mean") that restates the whole request replaces it, and
"<work> it and give it to X" gives X what the work made, from the thing of the request it
replaces (``screen.correction.thing_kept``: the first "it" is the thing, even with "and"
after it); a correction that is only a place or a facility ("no wait, the kitchenette")
replaces where the request took the thing, and the rest of the request stands
(``screen.correction``), never read as the request withdrawn."""

from __future__ import annotations

import pytest
from _offices import Row as _Row
from _offices import parser
from _offices import understood_tasks as _tasks


@pytest.mark.parametrize(
    ("name", "who", "text", "done"),
    [
        # the class's analogue: only the corrected request runs, the printout goes to Wang
        (
            "default",
            "lee",
            "print my file. no wait, print it and give it to Wang, he needs it",
            [("print", "file", "lee", "wang")],
        ),
        (
            "default",
            "lee",
            "print my file. sorry, I mean print it and then take it to Wang",
            [("print", "file", "lee", "wang")],
        ),
        (
            "harbour",
            "may",
            "scan my document. no wait, scan it and give it to Bill, he needs it at the door",
            [("copy", "document", "may", "bill")],
        ),
        # must not change: the same request said once, and a correction naming a new thing
        (
            "default",
            "lee",
            "print my file and give it to Wang, he needs it",
            [("print", "file", "lee", "wang")],
        ),
        (
            "default",
            "lee",
            "take my lunch to the kitchenette - no wait, give it to Wang",
            [("transfer", "lunch", "lee", "wang")],
        ),
        (
            "default",
            "lee",
            "bring me a stapler. actually, can you bring me a pen",
            [("transfer", "pen", None, "lee")],
        ),
    ],
)
def test_a_restated_request_replaces_the_one_before(
    name: str, who: str, text: str, done: list[_Row]
) -> None:
    assert _tasks(name, who, text) == done


@pytest.mark.parametrize(
    "text",
    [
        # the class's analogue: the place corrected, the reason sentence says the work
        "take my lunch to the microwave, no wait, the kitchenette. it needs warming",
        "take my lunch to the meeting room, no wait, the microwave",
        "take my lunch to the meeting room, no wait, to the microwave",
        "take my lunch to the meeting room - sorry, I meant the microwave",
    ],
)
def test_a_place_corrected_replaces_where_the_thing_goes(text: str) -> None:
    assert _tasks("default", "lee", text) == [("heat", "lunch", "lee", "lee")]


def test_a_place_corrected_to_a_room_reads_as_the_room_does() -> None:
    """ "take my lunch to the microwave, no wait, the kitchenette": read as "take my lunch to
    the kitchenette" (before, "no wait" withdrew it all): the kitchenette's one service on a
    lunch, its microwave's heating (``reading.room_service``)."""
    p = parser("default")
    said = p.parse("take my lunch to the kitchenette", "lee")
    frame = p.parse("take my lunch to the microwave, no wait, the kitchenette", "lee")
    assert said.tasks and frame.tasks == said.tasks and frame.question is None


@pytest.mark.parametrize(
    "text",
    [
        # must not change: a withdrawal after "no wait" still withdraws
        "take my lunch to the microwave, no wait, forget it",
        "take my lunch to the microwave. never mind, I ate it cold",
    ],
)
def test_a_withdrawal_after_the_place_still_withdraws(text: str) -> None:
    frame = parser("default").parse(text, "lee")
    assert not frame.tasks and frame.decline is not None and "dropped" in frame.decline
