"""A thing taken to a colleague to have work done on it and wanted back comes back (fix129d,
class 4): "can you take my declaration to Ivy to get it legalised? need it back by 3" handed
the document to Ivy after the work (a wrong physical action). "to get it <past participle>"
after "take X to P" is what P is there for, and "need it back" / "bring it back" makes the
requester the recipient (reading/taken_for_service.py). "take my signed contract to Wang" and
"take my report to Wang to get it copied" (no word of its return) are read as before."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.reading.taken_for_service import taken_for_service
from helpers.added_kinds import kind_added, signing_kind
from helpers.dataset_offices import default_office, harbour_office
from helpers.notary_office import notary_office
from helpers.reading import frame_reader, parser_for

_lin = frame_reader(default_office, "lin")
_may = frame_reader(harbour_office, "may")


@pytest.mark.parametrize(
    ("text", "kind"),
    [
        ("take my contract to Wang to get it signed? need it back by 5", "sign"),
        ("take my report to Wang to get it signed and bring it back", "sign"),
        ("can you take my contract to Wang to get it stamped? I need it back by 3", "seal"),
        ("take my report to Wang to get it copied? need it back by 5", "copy"),
        ("take my report to Wang to get it photocopied and bring it back", "copy"),
    ],
)
def test_the_work_is_done_and_the_thing_comes_back(text: str, kind: str) -> None:
    frame = _lin(text)
    got = [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]
    assert got == [(kind, "document", "lin", "lin")], frame


def test_the_same_in_harbour() -> None:
    frame = _may("take my document to Ray to get it signed and bring it back")
    got = [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]
    assert got == [("sign", "document", "may", "may")], frame


@pytest.mark.parametrize(
    "text",
    [
        "take my report to Wang to get it checked, need it back by 4",  # no such work here
    ],
)
def test_work_the_office_does_not_know_is_never_left_with_the_colleague(text: str) -> None:
    frame = _lin(text)
    assert all(t.recipient != "wang" for t in frame.tasks), frame
    assert frame.question is not None or frame.decline is not None, frame


def test_harbour_copy_wanted_back_is_not_left_with_the_colleague() -> None:
    frame = _may("take my document to Ray to get it copied? need it back by 5")
    assert all(t.recipient != "ray" for t in frame.tasks), frame


def test_a_kind_the_office_adds_comes_back_too() -> None:
    spec = signing_kind(
        "legalise", "legalise", "legalised", "legaliser", words=("legalise", "legalised")
    )
    with kind_added(spec):
        frame = parser_for(notary_office).parse(
            "can you take my affidavit to Hana to get it legalised? need it back by 3", "ruth"
        )
    got = [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks]
    assert got == [("legalise", "affidavit", "ruth", "ruth")], frame


@pytest.mark.parametrize(
    ("text", "kind", "recipient"),
    [
        ("take my signed contract to Wang", "transfer", "wang"),  # Wang keeps it
        ("take my report to Wang to get it copied", "copy", "wang"),  # no word of its return
    ],
)
def test_without_its_return_wanted_it_is_read_as_before(
    text: str, kind: str, recipient: str
) -> None:
    frame = _lin(text)
    got = [(t.kind, t.owner, t.recipient) for t in frame.tasks]
    assert got == [(kind, "lin", recipient)], frame


def test_the_clause_said_as_the_work_done_by_the_colleague() -> None:
    terms = parser_for(default_office).screen.terms
    said = taken_for_service(
        "take my contract to Wang to get it signed? need it back", terms.is_person_word
    )
    assert said == "get my contract signed by Wang? need it back"
    kept = "take my contract to the office to get it signed? need it back"
    assert taken_for_service(kept, terms.is_person_word) == kept
