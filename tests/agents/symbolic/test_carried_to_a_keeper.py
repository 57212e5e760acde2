"""A thing taken "to <colleague> in <place>" is handed to that colleague, wherever they are and
whatever service they keep there: no service verb is said, so none runs (round 166, class 4:
not reproduced on this tree, pinned here on offices where the colleague keeps the service that
works on the thing). Said with the service's participle, the service runs."""

from __future__ import annotations

import pytest
from _offices import tasks_of

from helpers.kit_room import kit_room
from helpers.reading import frame_reader

_kit = frame_reader(kit_room, "ana")  # Frank keeps the ingest desk, in the edit suite


@pytest.mark.parametrize(
    ("text", "item", "to"),
    [
        # the class's analogue
        ("take my camera card to Frank in the edit", "camera_card", "frank"),
        # variants: the room said in full, another keeper and place, "at", "over to"
        ("take my card to Frank in the edit suite", "camera_card", "frank"),
        ("bring my clippers to Gus in the workshop", "clippers", "gus"),
        ("could you take my badge over to Gus at the workshop", "badge", "gus"),
    ],
)
def test_the_thing_is_handed_to_the_keeper(text: str, item: str, to: str) -> None:
    frame = _kit(text)
    assert [(t.kind, t.item, t.owner, t.recipient, t.operation) for t in frame.tasks] == [
        ("transfer", item, "ana", to, None)
    ], frame


@pytest.mark.parametrize(
    ("office", "requester", "text", "to"),
    [
        ("harbour", "bill", "take my badge to Sue in the badge office", "sue"),
        ("harbour", "bill", "take my document to Mark in the copy room", "mark"),
    ],
)
def test_the_same_on_harbour(office: str, requester: str, text: str, to: str) -> None:
    assert [t[0] for t in tasks_of(office, text, requester)] == ["transfer"]
    assert [t[3] for t in tasks_of(office, text, requester)] == [to]


def test_the_service_asked_by_its_participle_still_runs() -> None:
    frame = _kit("take my card to the edit to be ingested")
    assert [(t.item, t.recipient, t.operation) for t in frame.tasks] == [
        ("camera_card", "ana", "ingest")
    ], frame
