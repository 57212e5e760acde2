"""A send-out facility said as the means (``screen.facility_means``): "send my form via the
courier desk to Leeds City Council", "put my letter in the post bag for Acme Ltd, Hull",
"could my letter go in the post bag to HMRC?", "can it go out with the courier today?" ask
for that facility's one send-out service with the speaker's thing, the destination kept
whole ("for ..." is where it goes). With no destination the service asks where, as it always
does; a destination said before, of the thing going back ("needs to go back to the
supplier, can it go out with the courier"), is where it goes. Taking a thing *to* the
facility, sending a file to a colleague, and a facility that sends nothing out read as
before."""

from __future__ import annotations

import pytest

from assistantx.core.office import Office, parse_office
from helpers.courier_room import courier_room
from helpers.dataset_offices import harbour_office, harbour_that_posts
from helpers.dispatch_office import dispatch_office, raw_dispatch_office
from helpers.reading import frame_reader

_dispatch = frame_reader(dispatch_office, "lena")
_courier_room = frame_reader(courier_room, "ana")
_harbour = frame_reader(harbour_that_posts, "may")


def _sent(frame: object) -> list[tuple[str | None, str | None, str | None, str | None]]:
    tasks = frame.tasks  # type: ignore[attr-defined]
    return [(t.item, t.owner, t.operation, t.destination) for t in tasks]


# -- class 3: the facility named as the means ------------------------------------------


@pytest.mark.parametrize(
    ("text", "sent"),
    [
        (
            "send my form via the post bag to Leeds City Council",
            ("letter", "post", "Leeds City Council"),
        ),
        ("put my letter in the post bag for Acme Ltd, Hull", ("letter", "post", "Acme Ltd, Hull")),
        (
            "pop my sample in the courier desk for the lab at Harwell",
            ("parcel", "courier", "the lab at Harwell"),
        ),
        ("send my cheque through the mail bag to HMRC", ("letter", "post", "HMRC")),
    ],
)
def test_dispatch_office_sends_by_the_named_facility(text: str, sent: tuple[str, str, str]) -> None:
    frame = _dispatch(text)
    assert frame.decline is None and frame.question is None, frame
    item, op, place = sent
    assert _sent(frame) == [(item, "lena", op, place)]


@pytest.mark.parametrize(
    ("text", "place"),
    [
        ("send my form via the courier desk to Leeds City Council", "Leeds City Council"),
        ("send my contract through the courier desk to Leeds", "Leeds"),
    ],
)
def test_courier_room_sends_by_its_desk(text: str, place: str) -> None:
    frame = _courier_room(text)
    assert frame.decline is None and frame.question is None, frame
    assert _sent(frame) == [("document", "ana", "courier", place)]


@pytest.mark.parametrize(
    ("text", "place"),
    [
        ("pop my letter in the post machine for Acme Ltd, Hull", "Acme Ltd, Hull"),
        ("send my letter via the franking machine to Hull", "Hull"),
    ],
)
def test_harbour_posts_by_its_franking_machine(text: str, place: str) -> None:
    frame = _harbour(text)
    assert frame.decline is None and frame.question is None, frame
    assert _sent(frame) == [("document", "may", "frank", place)]


# -- class 2: a thing going out with or in the facility --------------------------------


@pytest.mark.parametrize(
    ("text", "sent"),
    [
        ("could my letter go in the post bag to HMRC?", ("letter", "post", "HMRC")),
        (
            "My broken charger needs to go back to the supplier in Leeds, can it go out with "
            "the courier today?",
            ("parcel", "courier", "the supplier in Leeds"),
        ),
        (
            "my sample needs to go back to the lab, could it go with the courier?",
            ("parcel", "courier", "the lab"),
        ),
        (
            "can my postcard go in the mail bag to Acme Ltd, 12 Mill Lane?",
            ("letter", "post", "Acme Ltd, 12 Mill Lane"),
        ),
    ],
)
def test_a_thing_going_by_the_facility_is_sent(text: str, sent: tuple[str, str, str]) -> None:
    frame = _dispatch(text)
    assert frame.decline is None and frame.question is None, frame
    item, op, place = sent
    assert _sent(frame) == [(item, "lena", op, place)]


def test_harbour_thing_going_back_goes_through_its_mail_desk() -> None:
    frame = _harbour(
        "my form needs to go back to the Leeds tax office, can it go through the mail desk today?"
    )
    assert _sent(frame) == [("document", "may", "frank", "the Leeds tax office")]


@pytest.mark.parametrize(
    ("text", "asked"),
    [
        ("could my cheque go in the mail bag?", "Where should I post it to?"),
        ("can my charger go out with the courier?", "Where should I courier it to?"),
    ],
)
def test_with_no_destination_the_service_asks_where(text: str, asked: str) -> None:
    frame = _dispatch(text)
    assert frame.tasks == [] and frame.question is not None, frame
    assert frame.question.startswith(asked), frame.question


# -- must not change ---------------------------------------------------------------------


def test_taking_a_thing_to_the_facility_reads_as_before() -> None:
    # today a thing taken *to* a send-out facility is read as that service with no
    # destination, so the service asks where: kept as it was
    frame = _dispatch("take my form to the post bag")
    assert frame.tasks == [] and frame.question is not None, frame
    assert frame.question.startswith("Where should I post it to?"), frame.question
    frame = _courier_room("take my form to the courier desk")
    assert frame.tasks == [] and frame.question is not None, frame
    assert frame.question.startswith("Where should I courier it to?"), frame.question


def test_sending_to_a_colleague_is_a_delivery() -> None:
    frame = _dispatch("send my letter to Omar")
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("transfer", "letter", "omar")]
    frame = _harbour("send my file to Pat")
    assert [(t.kind, t.recipient) for t in frame.tasks] == [("send_file", "pat")]


def test_a_thing_the_facility_does_not_send_is_not_sent_by_another_service() -> None:
    frame = _dispatch("send my charger via the post bag to Hull")
    assert frame.tasks == [], frame


def test_a_facility_that_sends_nothing_out_is_no_means() -> None:
    # plain harbour franks envelopes and sends nothing out: "Hull" is asked about as before
    frame = frame_reader(harbour_office, "may")("pop my letter in the post machine for Hull")
    assert frame.tasks == [] and frame.question is not None, frame


def _goods_out() -> Office:
    """The dispatch office whose parcel service is called "returns" at a "goods out"
    hatch: only its verbs say how it sends ("ship", "courier")."""
    raw = raw_dispatch_office()
    courier = next(o for o in raw["operations"] if o["id"] == "courier")
    courier.update({"name": "returns", "verbs": ["ship", "courier", "send back"]})
    desk = next(f for f in raw["facilities"] if f["id"] == "courier_desk")
    desk.update({"name": "goods out", "synonyms": ["dispatch hatch"]})
    return parse_office(raw)


@pytest.mark.parametrize(
    "text",
    [
        # blind round 89's shape: the service named by a verb of its own that names a sender
        # (the supplier placed: a role alone asks where since fix129e)
        "My broken charger needs to go back to the supplier in Leeds, can it go out with the "
        "courier today?",
        "could my sample go with the courier to the lab",
    ],
)
def test_a_sender_named_by_the_services_own_verb_is_the_means(text: str) -> None:
    frame = frame_reader(_goods_out, "lena")(text)
    assert frame.decline is None and frame.question is None, frame
    assert [(t.item, t.operation) for t in frame.tasks] == [("parcel", "courier")]
    assert frame.tasks[0].destination in ("the supplier in Leeds", "the lab")


def _bag_and_fax_at_one_desk() -> Office:
    """The dispatch office whose letters go "in the diplomatic bag" from a desk that also faxes
    them: the desk names no one service, the bag names its own."""
    raw = raw_dispatch_office()
    post = next(o for o in raw["operations"] if o["id"] == "post")
    post.update({"name": "send in the diplomatic bag", "verbs": ["pouch"]})
    raw["operations"].append(
        {"id": "fax", "name": "fax", "verbs": ["fax"], "input": "letter", "sends_out": True}
    )
    bag = next(f for f in raw["facilities"] if f["id"] == "post_bag")
    bag.update({"name": "agency desk", "synonyms": [], "operations": ["post", "fax"]})
    return parse_office(raw)


@pytest.mark.parametrize(
    ("text", "sent"),
    [
        # blind round 91's shape: "send my customs declaration in the ship's bag to <a ship>"
        (
            "Please send my declaration in the diplomatic bag to the embassy at Lisbon",
            ("post", "the embassy at Lisbon"),
        ),
        ("can my form go in the diplomatic bag to the consulate?", ("post", "the consulate")),
        ("fax my form to 0113 496 0000", ("fax", "0113 496 0000")),
    ],
)
def test_a_service_named_by_what_it_sends_in_is_the_means(text: str, sent: tuple[str, str]) -> None:
    frame = frame_reader(_bag_and_fax_at_one_desk, "lena")(text)
    assert frame.decline is None and frame.question is None, frame
    assert [(t.operation, t.destination) for t in frame.tasks] == [sent]


def test_a_desk_of_two_services_said_as_the_means_names_neither() -> None:
    frame = frame_reader(_bag_and_fax_at_one_desk, "lena")(
        "send my form via the agency desk to Leeds"
    )
    assert not [t for t in frame.tasks if t.operation == "post"]
