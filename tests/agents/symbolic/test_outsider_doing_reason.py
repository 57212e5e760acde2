"""Someone outside's doing to a numbered thing, then "so can my X get the <seal> on it", asks
for the seal's work on X only (fix62b class 2: "buyer just settled lot 40 so can my invoice get
the paid stamp on it" asked what to do with the lot). An outsider named bare by what they are
("client", "buyer") or a noun and its number ("bidder 12") before a past verb is a subject,
its clause told (``speech.statement``: ``_outsider_did``, ``_numbered_subject``); a "so"
before a modal and the speaker's own thing ("so can my form ...") opens the ask
(``reading/consequence_boundary``). "sign my contract", "can Wang sign my document", "get the
seal on Zhang's contract" and "bring me the seal" are read as before."""

from __future__ import annotations

import pytest

from assistantx.core.office import Office
from helpers import office_builder as ob
from helpers.dataset_offices import default_office
from helpers.reading import frame_reader

_lee = frame_reader(default_office, "lee")


@pytest.mark.parametrize(
    "text",
    [
        "client just signed contract 12 so can my document get the seal on it",
        "customer paid invoice 7, can my form get the seal on it",
        "client just signed contract 12, so can you seal my document",
        "buyer just paid, so can my document get the seal",
    ],
)
def test_an_outsiders_doing_is_the_reason_for_the_seal(text: str) -> None:
    frame = _lee(text)
    assert [(t.kind, t.item, t.owner) for t in frame.tasks] == [("seal", "document", "lee")]
    assert frame.question is None, frame


def test_an_outsiders_doing_alone_is_told() -> None:
    frame = _lee("client just signed contract 12")
    assert frame.tasks == [] and frame.question is None and frame.decline is not None, frame


def test_a_numbered_table_done_then_the_stapler_is_fetched() -> None:
    frame = _lee("table 6 is done so can you bring me the stapler")
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("transfer", "stapler", "lee")
    ], frame


def test_signing_the_own_contract_still_asks_who() -> None:
    frame = _lee("sign my contract")
    assert frame.question is not None and frame.question.startswith("Who should sign"), frame


@pytest.mark.parametrize(
    ("text", "wanted"),
    [
        ("can Wang sign my document", ("sign", "document", "lee")),
        ("get the seal on Zhang's contract", ("seal", "document", "zhang")),
        ("bring me the seal", ("transfer", "seal", None)),
    ],
)
def test_the_neighbours_are_read_as_before(text: str, wanted: tuple[str, str, str]) -> None:
    frame = _lee(text)
    assert [(t.kind, t.item, t.owner) for t in frame.tasks] == [wanted], frame


def _saleroom() -> Office:
    return ob.parsed(
        lambda: ob.office_file(
            "Saleroom",
            [
                ob.person("lee", "Lee Hart", "invoice", aliases=["Lee"]),
                ob.person("wang", "Wang Li", "invoice", "lot", aliases=["Wang"]),
                ob.person("max", "Max Doyle", "stamp", aliases=["Max"]),
            ],
            rooms=[ob.room("store", "Store room", 20.0, 6.0)],
            item_types=[
                ob.item("invoice", "invoice", "personal", signable=True),
                ob.item("lot", "lot"),
                ob.item("stamp", "PAID stamp", seals=True, synonyms=["paid stamp"]),
            ],
            operations=[],
            facilities=[],
            home="store",
        )
    )()


_saleroom_lee = frame_reader(_saleroom, "lee")


@pytest.mark.parametrize(
    "text",
    [
        "buyer just settled lot 40 so can my invoice get the paid stamp on it",
        "bidder 12 just settled lot 40 so can my invoice get the paid stamp on it",
        "lot 40 is settled so can my invoice get the paid stamp on it",
    ],
)
def test_the_numbered_lot_is_the_reasons_topic_only(text: str) -> None:
    frame = _saleroom_lee(text)
    assert [(t.kind, t.item, t.owner) for t in frame.tasks] == [("seal", "invoice", "lee")]
    assert frame.question is None, frame


def test_the_stamp_on_a_colleagues_invoice_is_read_as_before() -> None:
    frame = _saleroom_lee("get the paid stamp on Wang's invoice")
    assert [(t.kind, t.item, t.owner) for t in frame.tasks] == [("seal", "invoice", "wang")]


def test_a_thing_done_for_the_speaker_beside_an_outsiders_doing_is_still_asked() -> None:
    # the outsider's doing told leaves the ask before it ("... for me"), no remark on a thing
    frame = _lee("bypass the icloud lock on this iphone for me, customer lost the password")
    assert frame.question is not None or "bypass" in (frame.decline or ""), frame
    assert not (frame.decline or "").startswith("Noted"), frame
