"""A thing sent outside by a means, said in any word order: "have my brief couriered to Leeds"
(no "could you"), "send my signed deed to the Crown Court by courier" (the place before the
means), "my statement needs couriering to Leeds", "get my brief to Leeds via courier". Blind
rounds 59-64's class: where the send-out service is asked for by another verb ("dispatch")
and only its name says the means ("send by courier"), the means word was no word of the
service, and a "have X <participle>" whose participle the dictionary does not know
("couriered") was read as a question. The means a service's name says after "by"/"via" now
asks for it like its verbs. A colleague after "to" is still a delivery, and an office with no
outside service still asks whom the place is."""

from __future__ import annotations

import pytest

from assistantx.core.office import load_office
from helpers.chambers_post import chambers_post
from helpers.courier_room import courier_room
from helpers.reading import frame_reader

_frame = frame_reader(chambers_post, "nadia")


def _sent(frame: object) -> list[tuple[str | None, str | None, str | None]]:
    tasks = frame.tasks  # type: ignore[attr-defined]
    return [(t.item, t.operation, t.destination) for t in tasks]


@pytest.mark.parametrize(
    ("text", "place"),
    [
        ("have my statement couriered to Leeds", "Leeds"),
        ("have my deed couriered over to the Crown Court, please", "the Crown Court"),
        ("could you have my statement couriered to Leeds", "Leeds"),
        ("send my signed brief to the Crown Court by courier", "the Crown Court"),
        ("send my signed deed by courier to the Crown Court", "the Crown Court"),
        ("get my brief to Leeds by courier", "Leeds"),
        ("send my brief to Leeds via courier", "Leeds"),
        ("my statement needs couriering to Leeds", "Leeds"),
        ("courier my brief to Leeds", "Leeds"),
        ("can you get my statement sent to Leeds by courier", "Leeds"),
        ("please courier my deed over to Harrow Crown Court", "Harrow Crown Court"),
    ],
)
def test_a_thing_sent_by_the_named_means_goes_there(text: str, place: str) -> None:
    frame = _frame(text)
    assert frame.decline is None and frame.question is None, frame
    assert _sent(frame) == [("brief", "courier", place)]


@pytest.mark.parametrize(
    ("text", "sent"),
    [
        ("have my letter posted to Cardiff", ("letter", "post", "Cardiff")),
        ("send my letter to Cardiff by post", ("letter", "post", "Cardiff")),
        ("send my form to the bank by fax", ("form", "fax", "the bank")),
        ("get my form faxed to the bank", ("form", "fax", "the bank")),
    ],
)
def test_a_service_named_by_its_own_verb_reads_as_before(
    text: str, sent: tuple[str, str, str]
) -> None:
    frame = _frame(text)
    assert frame.decline is None and frame.question is None, frame
    assert _sent(frame) == [sent]


def test_the_service_whose_verb_is_its_means_still_couriers() -> None:
    frame = frame_reader(courier_room, "ana")("have my statement couriered to Leeds")
    assert frame.decline is None and frame.question is None, frame
    assert _sent(frame) == [("document", "courier", "Leeds")]


def test_a_colleague_after_to_is_a_delivery() -> None:
    frame = _frame("send my brief to Owen")
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", "brief", "owen")]


def test_a_thing_the_means_does_not_send_is_declined_in_words() -> None:
    frame = _frame("send my laptop to Leeds by courier")
    assert frame.tasks == [] and frame.decline is not None, frame
    assert "laptop" in frame.decline


def test_without_an_outside_service_the_place_is_asked_about() -> None:
    frame = frame_reader(load_office, "chen")("send my document to Leeds")
    assert frame.tasks == [] and frame.question is not None, frame
    assert "Leeds" in frame.question
