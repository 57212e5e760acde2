"""A place outside said by its proper name names nothing of the office (fix61b): "send my job
off for hallmarking at the Birmingham Assay Office" assayed the job in the workshop, its
"Assay" read as the office's service; "to the Leeds Print Works" printed, "to the Baker Street
office" asked whether Sam Baker was meant. Capitalised words after "to", "at", "for" or
"from" that end in the noun of a kind of place, a firm or a street ("Office", "Works", "Ltd",
"Street"), or are followed by such a noun ("the Baker Street office"), are the place's name
whole (``reading.outside_name``); "at" before such a name says where a send-out sends, as
"to" does; the gerund after "for" ("for hallmarking") names the service. The office's own
names said in capitals ("at the Copy Room") stay its own."""

from __future__ import annotations

import pytest

from assistantx.core.task_schema import TaskFrame
from helpers.courier_room import courier_room
from helpers.dataset_offices import harbour_office
from helpers.goldsmiths import goldsmiths
from helpers.printshop import printshop
from helpers.reading import frame_reader

_lee = frame_reader(goldsmiths, "lee")
_bjorn = frame_reader(courier_room, "bjorn")
_edda = frame_reader(printshop, "edda")
_may = frame_reader(harbour_office, "may")
_mark = frame_reader(harbour_office, "mark")


def _sent(frame: TaskFrame) -> list[tuple[str | None, str | None, str | None]]:
    return [(t.operation, t.item, t.destination) for t in frame.tasks]


def _operations(frame: TaskFrame) -> list[str | None]:
    return [t.operation for t in frame.tasks]


# -- 1. a service's word inside the place's name -------------------------------------------


@pytest.mark.parametrize(
    ("text", "destination"),
    [
        (
            "Send my job off for hallmarking at the Birmingham Assay Office.",
            "the Birmingham Assay Office",
        ),
        ("hallmark my job at the Birmingham Assay Office", "the Birmingham Assay Office"),
        ("send my job off for hallmarking at the Leeds Depot", "the Leeds Depot"),
        # as before
        (
            "send my job off for hallmarking to the Birmingham Assay Office",
            "the Birmingham Assay Office",
        ),
        ("send my piece off for hallmarking at Birmingham", "Birmingham"),
    ],
)
def test_the_gerund_names_the_service_and_the_name_after_at_is_the_place(
    text: str, destination: str
) -> None:
    frame = _lee(text)
    assert frame.question is None and frame.decline is None, frame
    assert _sent(frame) == [("hallmark", "job", destination)], frame


@pytest.mark.parametrize(
    ("text", "destination"),
    [
        ("courier my job to the Leeds Print Works", "the Leeds Print Works"),
        ("courier my job to the Birmingham Assay Office", "the Birmingham Assay Office"),
        ("courier my job to the Leeds Courier Depot", "the Leeds Courier Depot"),
        ("courier my job to Leeds", "Leeds"),
    ],
)
def test_a_courier_to_a_place_named_with_a_service_word_is_the_courier(
    text: str, destination: str
) -> None:
    frame = _lee(text)
    assert _sent(frame) == [("courier", "job", destination)], frame


def test_a_plain_send_to_the_named_place_never_assays() -> None:
    """Two send-outs take a job, so "send" alone says neither; the name's "Assay" is no
    third choice done in the workshop."""
    frame = _lee("send my job to the Birmingham Assay Office")
    assert "assay" not in _operations(frame), frame


@pytest.mark.parametrize(
    ("text", "operation"),
    [
        ("assay my job", "assay"),
        ("xrf my piece", "assay"),
        ("print my report", "print"),
        ("print my report at the Front Desk", "print"),  # the office's own place
    ],
)
def test_the_services_said_as_verbs_are_still_asked(text: str, operation: str) -> None:
    frame = _lee(text)
    assert frame.question is None, frame
    assert [t.operation or operation for t in frame.tasks] == [operation], frame


def test_hallmarking_with_no_place_still_asks_where() -> None:
    frame = _lee("send my job off for hallmarking")
    assert frame.tasks == [] and frame.question is not None
    assert frame.question.startswith("Where should I hallmark it to?"), frame


def test_a_service_that_is_no_send_out_for_a_place_outside_prints_nothing() -> None:
    """ "for signing": the signing asked (who signs is asked), never the name's "Copy"."""
    frame = _bjorn("send my contract off for signing at the Harbour Copy Centre")
    assert frame.tasks == [] and frame.question is not None, frame
    assert "sign" in frame.question, frame


def test_the_office_printer_said_with_its_room_still_prints() -> None:
    assert [t.kind for t in _bjorn("print my contract at the print room").tasks] == ["copy"]


def test_engraving_asked_at_a_print_works_engraves_only() -> None:
    assert _operations(_edda("send my proof off for engraving at the Leeds Print Works")) == [
        "engrave"
    ]


def test_posting_to_a_firm_named_like_a_service_posts() -> None:  # as before
    frame = _edda("post my proof to Print Express Ltd")
    assert _sent(frame) == [("post", "proof", "Print Express Ltd")], frame


@pytest.mark.parametrize(
    "text",
    [
        "post my document to the Leeds Print Works",
        "post my document to Print Express Ltd",
        "post my document to the Harbour Scan Centre",
    ],
)
def test_harbour_never_prints_nor_scans_for_a_place_named_so(text: str) -> None:
    """Harbour's franking does not send out: the place is asked about, never read as its
    printing or scanning."""
    assert not {"print", "copy"} & {t.kind for t in _may(text).tasks}  # a scan is a copy


def test_scanning_at_a_print_works_scans_only() -> None:
    frame = _may("scan my document at the Leeds Print Works")
    assert [t.kind for t in frame.tasks] == ["copy"], frame


@pytest.mark.parametrize(
    ("text", "kind"),
    [("print my document at the Copy Room", "print"), ("scan my document", "copy")],
)
def test_harbour_services_at_its_own_rooms_as_before(text: str, kind: str) -> None:
    assert [t.kind for t in _may(text).tasks] == [kind]


# -- 2. a colleague's or a thing's name inside the place's name ----------------------------


@pytest.mark.parametrize(
    ("text", "destination"),
    [
        ("courier my job to the Baker Street office", "the Baker Street office"),
        ("courier my job to Stapler House", "Stapler House"),
    ],
)
def test_a_colleague_or_a_thing_inside_the_name_is_the_place(text: str, destination: str) -> None:
    frame = _lee(text)
    assert frame.question is None, frame
    assert _sent(frame) == [("courier", "job", destination)], frame


@pytest.mark.parametrize(
    "text", ["take my ring to Baker Street", "take my ring to the Baker Street office"]
)
def test_a_street_named_after_a_colleague_is_not_the_colleague(text: str) -> None:
    frame = _lee(text)
    assert all(t.recipient != "sam" for t in frame.tasks), frame
    assert "Sam Baker" not in (frame.question or ""), frame


def test_a_harbour_street_named_after_a_colleague_is_not_the_colleague() -> None:
    frame = _mark("take my ruler to the Will Street office")
    assert "Will Tanaka" not in (frame.question or ""), frame
    assert all(t.recipient != "will" for t in frame.tasks), frame


@pytest.mark.parametrize(
    ("text", "recipient", "owner"),
    [
        ("take my ring to Sam Baker", "sam", "lee"),
        ("take my stapler to Baker office", "sam", "lee"),  # his office, said bare
        ("bring me Sam Baker's ring", "lee", "sam"),
        ("bring me Ada's stapler", "lee", "ada"),
    ],
)
def test_the_colleague_said_alone_is_still_the_colleague(
    text: str, recipient: str, owner: str
) -> None:
    frame = _lee(text)
    assert [(t.recipient, t.owner) for t in frame.tasks] == [(recipient, owner)], frame
