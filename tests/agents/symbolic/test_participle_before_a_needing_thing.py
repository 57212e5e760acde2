"""A past participle between "my"/"the" and the thing it describes, with the thing's own task
word right after it ("my *signed* contract needs couriering to ..."): the participle is the
state the thing is in, never the statement's verb ("signed it") nor a task asked for ("sign
it"). The need after it is read as for the thing said bare: the requester's own thing sent
out to the destination said, the destination kept whole. Without a task word after it ("my
printed agenda please") and where the thing's state is only told ("my signed contract is on
my desk") it is read as before."""

from __future__ import annotations

import functools

import pytest

from helpers.chambers_post import chambers_post
from helpers.courier_room import courier_room
from helpers.dataset_offices import default_office_that_sends_out, harbour_that_posts
from helpers.reading import frame_reader

_courier_room = frame_reader(courier_room, "ana")
_chambers = frame_reader(chambers_post, "nadia")
_harbour = frame_reader(harbour_that_posts, "may")
_default = frame_reader(
    functools.partial(
        default_office_that_sends_out, "courier", "send by courier", "courier", "the address"
    ),
    "chen",
)
_default_fax = frame_reader(
    functools.partial(default_office_that_sends_out, "fax", "fax", "fax", "the fax number"),
    "chen",
)


def _sent(frame: object) -> list[tuple[str | None, str | None, str | None, str | None]]:
    tasks = frame.tasks  # type: ignore[attr-defined]
    return [(t.item, t.owner, t.operation, t.destination) for t in tasks]


@pytest.mark.parametrize(
    ("text", "place"),
    [
        (
            "my signed contract needs couriering to the council offices on Bridge Street",
            "the council offices on Bridge Street",
        ),
        ("my signed statement needs couriering to Leeds", "Leeds"),
        ("the printed agenda needs couriering to Hull", "Hull"),
        ("my stamped invoice needs couriering to Acme Ltd, 12 Mill Lane", "Acme Ltd, 12 Mill Lane"),
    ],
)
def test_courier_room_sends_the_described_own_thing(text: str, place: str) -> None:
    frame = _courier_room(text)
    assert frame.decline is None and frame.question is None, frame
    assert _sent(frame) == [("document", "ana", "courier", place)]


@pytest.mark.parametrize(
    ("text", "place"),
    [
        ("my signed letter needs posting to Acme Ltd, 12 Mill Lane", "Acme Ltd, 12 Mill Lane"),
        ("my signed statement needs couriering to the county court", "the county court"),
    ],
)
def test_chambers_sends_the_described_own_thing(text: str, place: str) -> None:
    frame = _chambers(text)
    assert frame.decline is None and frame.question is None, frame
    assert [(t.owner, t.destination) for t in frame.tasks] == [("nadia", place)]
    assert frame.tasks[0].operation in ("post", "courier")


@pytest.mark.parametrize(
    ("text", "place"),
    [
        ("my stamped invoice needs posting to Acme Ltd, 12 Mill Lane", "Acme Ltd, 12 Mill Lane"),
        ("my signed form has to be posted to Hull", "Hull"),
        ("my printed letter needs posting to the tax office on Quay Road", None),
    ],
)
def test_harbour_posts_the_described_own_thing(text: str, place: str | None) -> None:
    frame = _harbour(text)
    assert frame.decline is None and frame.question is None, frame
    assert _sent(frame) == [("document", "may", "frank", place or "the tax office on Quay Road")]


@pytest.mark.parametrize(
    ("read", "text", "sent"),
    [
        (
            _default,
            "my signed contract needs couriering to the council offices on Bridge Street",
            ("document", "chen", "courier", "the council offices on Bridge Street"),
        ),
        (
            _default,
            "our printed form needs to be couriered to Leeds City Council",
            ("document", "chen", "courier", "Leeds City Council"),
        ),
        (
            _default_fax,
            "my signed form needs faxing to the bank",
            ("document", "chen", "fax", "the bank"),
        ),
    ],
)
def test_default_office_sends_the_described_own_thing(
    read: object, text: str, sent: tuple[str, str, str, str]
) -> None:
    frame = read(text)  # type: ignore[operator]
    assert frame.decline is None and frame.question is None, frame
    assert _sent(frame) == [sent]


# -- must not change ---------------------------------------------------------------------


@pytest.mark.parametrize("read", [_courier_room, _harbour, _default])
def test_a_thing_that_needs_signing_still_asks_the_signer(read: object) -> None:
    frame = read("my contract needs signing")  # type: ignore[operator]
    assert frame.tasks == [] and frame.question is not None, frame
    assert "Who should sign" in frame.question


@pytest.mark.parametrize("read", [_courier_room, _harbour, _default])
def test_a_described_thing_only_told_of_is_noted(read: object) -> None:
    frame = read("my signed contract is on my desk")  # type: ignore[operator]
    assert frame.tasks == [] and frame.decline is not None, frame


def test_a_participle_with_no_task_word_after_still_asks_for_its_work() -> None:
    frame = _courier_room("my printed agenda please")
    assert [(t.kind, t.item, t.owner) for t in frame.tasks] == [("copy", "document", "ana")]
