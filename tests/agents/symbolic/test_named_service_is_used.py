"""The service the requester names is the service used, never swapped for another. A means
a send-out service's name says ("send by courier": "courier") names that service as its
verbs do (``reading.operations``): "courier my form to Leeds City Council" where the courier
takes only briefs is declined, no longer faxed. A means of sending the office has no service
for (``screen.unoffered_means``): "can my contract go out with the courier to Leeds?" where
only the franking machine posts is said not to be here and what the office has is offered
("Shall I frank it instead?"; a yes franks it, a no does nothing). A request naming no means
keeps the office's one service for the thing, and a means the office has is used."""

from __future__ import annotations

import pytest

from helpers.chambers_post import chambers_post
from helpers.courier_room import courier_room
from helpers.dataset_offices import default_office_that_sends_out, harbour_that_posts
from helpers.dispatch_office import dispatch_office
from helpers.reading import answered_reader, frame_reader

_chambers = frame_reader(chambers_post, "nadia")
_harbour = frame_reader(harbour_that_posts, "may")
_courier_room = frame_reader(courier_room, "ana")
_dispatch = frame_reader(dispatch_office, "lena")


def _faxing_default() -> object:
    return default_office_that_sends_out("fax", "fax", "fax", "the fax number")


_default = frame_reader(_faxing_default, "mao")  # type: ignore[arg-type]


def _sent(frame: object) -> list[tuple[str | None, str | None, str | None]]:
    tasks = frame.tasks  # type: ignore[attr-defined]
    return [(t.item, t.operation, t.destination) for t in tasks]


# -- the means said is its service's, which declines a thing it does not take ------------


@pytest.mark.parametrize(
    ("text", "thing"),
    [
        ("courier my form to Leeds City Council", "form"),
        ("send my form by courier to Leeds City Council", "form"),
        ("could you courier my letter to HMRC?", "letter"),
        ("could my form go out with the courier to Leeds?", "form"),
        ("have my letter couriered to the bank", "letter"),
    ],
)
def test_chambers_never_swaps_the_courier(text: str, thing: str) -> None:
    frame = _chambers(text)
    assert frame.tasks == [] and frame.decline is not None, frame
    assert f"a {thing}" in frame.decline and "briefs" in frame.decline, frame


@pytest.mark.parametrize(
    ("text", "sent"),
    [
        ("courier my brief to Leeds", ("brief", "courier", "Leeds")),
        ("send my letter with the post to Hull", ("letter", "post", "Hull")),
        ("send my form by fax to the bank", ("form", "fax", "the bank")),
        # neighbours: no means said keeps the one service for the thing; a number is faxed
        ("send my form to Leeds City Council", ("form", "fax", "Leeds City Council")),
        ("fax my form to 0113 496 0000", ("form", "fax", "0113 496 0000")),
    ],
)
def test_chambers_uses_the_service_named_or_the_one_that_takes_it(
    text: str, sent: tuple[str, str, str]
) -> None:
    frame = _chambers(text)
    assert frame.question is None and frame.decline is None, frame
    assert _sent(frame) == [sent]


# -- a means the office has no service for is said so, and what it has offered ------------


@pytest.mark.parametrize(
    ("read", "text", "offered"),
    [
        (_harbour, "can my contract go out with the courier to Leeds?", "frank"),
        (_harbour, "send my letter by courier to Hull", "frank"),
        (_courier_room, "could my letter go out with the post to Hull?", "courier"),
        (_courier_room, "send my contract by fax to the bank", "courier"),
        (_default, "send my document by courier to Leeds", "fax"),
        (_default, "could my contract go out with the post to Hull?", "fax"),
    ],
)
def test_a_means_not_here_is_offered_instead(read: object, text: str, offered: str) -> None:
    frame = read(text)  # type: ignore[operator]
    assert frame.tasks == [], frame
    assert frame.question is not None and frame.question.startswith("There's no "), frame
    assert frame.question.endswith(f"Shall I {offered} it instead?"), frame


@pytest.mark.parametrize(
    ("office", "who", "text", "sent"),
    [
        (
            harbour_that_posts,
            "may",
            "can my contract go out with the courier to Leeds?",
            ("document", "frank", "Leeds"),
        ),
        (
            courier_room,
            "ana",
            "could my letter go out with the post to Hull?",
            ("document", "courier", "Hull"),
        ),
    ],
)
def test_a_yes_uses_the_service_offered_and_a_no_nothing(
    office: object, who: str, text: str, sent: tuple[str, str, str]
) -> None:
    read = answered_reader(office, who)  # type: ignore[arg-type]
    assert _sent(read(text, ["yes"])) == [sent]
    refused = read(text, ["no"])
    assert refused.tasks == [] and refused.decline is not None, refused


def test_several_ways_here_are_asked_about() -> None:
    frame = _dispatch("send my letter by fax to HMRC")
    assert frame.tasks == [], frame
    assert frame.question is not None and "courier or post" in frame.question, frame


@pytest.mark.parametrize(
    ("read", "text", "sent"),
    [
        # neighbours: the means the office has is its own service ("post" is the franker's)
        (_harbour, "send my letter by post to Hull", ("document", "frank", "Hull")),
        (
            _harbour,
            "can my contract go out with the post to Leeds?",
            ("document", "frank", "Leeds"),
        ),
        (
            _courier_room,
            "could my contract go out with the courier to Hull?",
            ("document", "courier", "Hull"),
        ),
        (_default, "send my document by fax to the bank", ("document", "fax", "the bank")),
    ],
)
def test_a_means_the_office_has_is_used(
    read: object, text: str, sent: tuple[str, str, str]
) -> None:
    frame = read(text)  # type: ignore[operator]
    assert frame.question is None and frame.decline is None, frame
    assert _sent(frame) == [sent]


@pytest.mark.parametrize(
    ("read", "text"),
    [
        (_courier_room, "can you get me the contract that came in the post?"),
        (_harbour, "bring me the letter that came by courier"),
    ],
)
def test_how_a_thing_came_asks_for_no_means(read: object, text: str) -> None:
    frame = read(text)  # type: ignore[operator]
    question = frame.question or ""
    assert not question.startswith("There's no "), frame
