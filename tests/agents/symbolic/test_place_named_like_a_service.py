"""A place of the office named like one of its services is a place, not the service (fix103d,
class 1): a room whose one-word name is also a service's verb ("Dispatch", where the courier
desk dispatches) is the place after a preposition of where ("with Mateus *in* dispatch",
"*from* dispatch"), and a facility said as where a thing lives ("the meter that *lives in*
the drying cabinet", "*kept on* the laminator") is where to fetch it from, not its service.
Read from each office's own locations and facilities (``reading.verb_named_places``,
``reading.where_it_lives``); the verb said as a verb and the thing put in the machine still
ask for the service."""

from __future__ import annotations

import pytest
from _offices import tasks_of
from symbolic_run import run_instruction

from assistantx.core.office import Office, parse_office
from helpers.reading import frame_reader
from helpers.seed_lab import raw_seed_lab, seed_lab

_lab = frame_reader(seed_lab, "ines")


def _room_named_like_its_facility() -> Office:
    """The seed lab where the drying cabinet is also called after its room ("the drying
    room"): the room's name is the facility's too."""
    raw = raw_seed_lab()
    for f in raw["facilities"]:
        if f["id"] == "drying_cabinet":
            f["synonyms"] = ["drying room"]
    return parse_office(raw, "seed lab, cabinet named after its room")


_named_room = frame_reader(_room_named_like_its_facility, "ines")


def _two_word_dispatch_room() -> Office:
    """The seed lab where the room is the "Dispatch room": said "dispatch" alone, the kind of
    place left out, as people do."""
    raw = raw_seed_lab()
    for loc in raw["locations"]:
        if loc["id"] == "dispatch":
            loc["name"] = "Dispatch room"
    return parse_office(raw, "seed lab, a two-word dispatch room")


_dispatch_room = frame_reader(_two_word_dispatch_room, "ines")


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        (
            "pls drop my pocket balance off with Mateus in dispatch",
            [("transfer", "pocket_balance", "ines", "mateus", None)],
        ),
        (
            "bring me Rania's stapler from dispatch",
            [("transfer", "stapler", "rania", "ines", None)],
        ),
    ],
)
def test_a_two_word_room_said_by_its_service_verb_alone_is_the_room(
    text: str, expected: list[tuple[str, str, str, str, None]]
) -> None:
    frame = _dispatch_room(text)
    assert _tasks(frame) == expected, frame


def test_the_verb_of_a_two_word_room_still_asks_for_the_service() -> None:
    frame = _dispatch_room("please dispatch my contract to Acme Ltd")
    assert [t.operation for t in frame.tasks] == ["courier"], frame


def _tasks(frame: object) -> list[tuple[str, str | None, str | None, str | None, str | None]]:
    return [(t.kind, t.item, t.owner, t.recipient, t.operation) for t in frame.tasks]  # type: ignore[attr-defined]


@pytest.mark.parametrize(
    ("text", "item", "owner", "recipient"),
    [
        # the class's own analogue: a drop-off with a colleague who is in Dispatch
        (
            "pls drop my pocket balance off with Mateus in dispatch",
            "pocket_balance",
            "ines",
            "mateus",
        ),
        ("take my pocket balance to Mateus at dispatch", "pocket_balance", "ines", "mateus"),
        ("leave my pocket balance with Mateus in the dispatch", "pocket_balance", "ines", "mateus"),
        # where a thing is taken from
        ("bring me Rania's stapler from dispatch", "stapler", "rania", "ines"),
        ("can I have Rania's stapler out of dispatch", "stapler", "rania", "ines"),
    ],
)
def test_a_room_named_by_a_service_verb_is_the_room_after_where(
    text: str, item: str, owner: str, recipient: str
) -> None:
    frame = _lab(text)
    assert _tasks(frame) == [("transfer", item, owner, recipient, None)], frame


@pytest.mark.parametrize(
    "text",
    [
        "I need the moisture meter that lives in the drying cabinet, Seun's one",
        "I need the moisture meter that lives in the drying cabinet",
        "could you grab me the moisture meter that's kept in the drying cabinet",
        "fetch me the moisture meter that usually sits over in the drying cabinet",
    ],
)
def test_a_facility_where_a_thing_lives_is_where_to_fetch_it(text: str) -> None:
    frame = _lab(text)
    assert [(t.kind, t.item, t.operation) for t in frame.tasks] == [
        ("transfer", "moisture_meter", None)
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        "I need the moisture meter that lives in the drying room, Seun's one",
        "get me the moisture meter that's stored in the drying room",
    ],
)
def test_a_room_whose_name_is_also_its_facilitys_is_where_the_thing_lives(text: str) -> None:
    frame = _named_room(text)
    assert [(t.kind, t.item, t.operation) for t in frame.tasks] == [
        ("transfer", "moisture_meter", None)
    ], frame


@pytest.mark.parametrize(
    ("office", "requester", "text", "expected"),
    [
        ("harbour", "may", "get me the ruler that's kept on the laminator", ("ruler", None)),
        ("harbour", "may", "I need the tape that lives in the stationery cupboard", ("tape", None)),
        ("default", "sun", "could you fetch me the cup that lives in the microwave", ("cup", None)),
        ("default", "sun", "leave my book with Wang in the meeting room", ("book", "wang")),
        (
            "harbour",
            "may",
            "drop my calculator off with Will at the post desk",
            ("calculator", "will"),
        ),
    ],
)
def test_the_same_on_the_dataset_offices(
    office: str, requester: str, text: str, expected: tuple[str, str | None]
) -> None:
    item, recipient = expected
    tasks = tasks_of(office, text, requester)
    assert [(k, i) for k, i, _, _ in tasks] == [("transfer", item)], tasks
    if recipient is not None:
        assert tasks[0][3] == recipient, tasks


def test_a_thing_fetched_from_the_print_room_is_not_printed() -> None:
    tasks = tasks_of("default", "bring me Zhang's stapler from the print room", "sun")
    assert tasks == [("transfer", "stapler", "zhang", "sun")], tasks


# -- must not change: the service said as a verb, or the thing put in its machine -----------
@pytest.mark.parametrize(
    ("text", "item", "operation"),
    [
        ("dry my seed samples", "seed_sample", "dry"),
        ("put my seed samples in the drying cabinet", "seed_sample", "dry"),
        ("my seed samples need to sit in the drying cabinet", "seed_sample", "dry"),
        ("courier my contract to the supplier at 3 Mill Lane", "document", "courier"),
        ("dispatch my contract to Acme Ltd", "document", "courier"),
    ],
)
def test_the_service_asked_for_is_still_run(text: str, item: str, operation: str) -> None:
    frame = _lab(text)
    assert [(t.item, t.operation) for t in frame.tasks] == [(item, operation)], frame


def test_the_dispatched_paper_still_goes_where_it_was_sent() -> None:
    [task] = _lab("please dispatch my contract to Acme Ltd").tasks
    assert task.destination == "Acme Ltd", task


def test_a_lunch_put_in_the_microwave_is_still_heated() -> None:
    # fix129e: lee has lunch in the fridge (sun has none: asked where it is)
    assert tasks_of("default", "put my lunch in the microwave", "lee") == [
        ("heat", "lunch", "lee", "lee")
    ]


async def test_the_pocket_balance_reaches_mateus() -> None:
    run = await run_instruction(
        seed_lab(), "ines", "pls drop my pocket balance off with Mateus in dispatch"
    )
    trace = run.stm.trace
    assert trace.outcome == "done", trace.summary
    assert run.sim.world.holder.get("pocket_balance:ines") == "mateus", trace.summary
