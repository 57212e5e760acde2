"""A send-out's "to" phrase that names only someone's role or a firm by what it does ("courier
my book to my agent pls", "to the supplier", "to our lawyers", "to the other side's
solicitors") says whom, never where (``reading.role_destination``): the service asks its own
question for where it goes, never sends the thing "to the supplier". A proper name ("Westgate
branch", "Bodegas Ruiz in Madrid"), a place ("the client's office", "the rowing club") or an
address ("the lawyer at 12 High Street") is where, and is sent as said. Until fix129e an outside
firm said by its role ("the supplier", "the client", "our lawyers") was sent as said; two
outside testers expected a question for "the importer" and "the other side's solicitors"."""

from __future__ import annotations

import functools
from typing import Any

import pytest

from assistantx.agents.symbolic.reading.role_destination import names_only_a_role
from assistantx.core.office import Office, parse_office
from helpers.dataset_offices import HARBOUR_FILE
from helpers.library_courier import library_courier
from helpers.reading import frame_reader
from helpers.yaml_files import raw_yaml


@functools.cache
def _harbour_courier() -> Office:
    """Harbour with a courier at its post desk that sends a document out, asking "the
    address" when none is said."""
    raw: dict[str, Any] = raw_yaml(HARBOUR_FILE)
    raw["operations"].append(
        {
            "id": "courier",
            "name": "send by courier",
            "verbs": ["courier"],
            "input": "document",
            "sends_out": True,
            "destination_asked": "the address",
        }
    )
    raw["facilities"].append(
        {
            "id": "courier_point",
            "name": "courier point",
            "location": "post_desk",
            "operations": ["courier"],
            "guards": ["mark"],
            "products": [],
        }
    )
    return parse_office(raw)


_LIBRARY = frame_reader(library_courier, "wu")
_HARBOUR = frame_reader(_harbour_courier, "will")


@pytest.mark.parametrize(
    "text",
    [
        "courier my book to my agent pls",  # the class's analogue
        "courier my book to my lawyer",
        "courier my book to our accountant",
        "courier my book to her solicitor",
        "courier my book to my literary agent please",
        # since fix129e: a firm or a role said with "the", or in the plural
        "courier my book to the lawyer",
        "courier my book to the client",
        "courier my book to our lawyers",
        "courier my book to the importer",
        "courier my book to the shipping agent's accountants",
    ],
)
def test_a_role_is_no_destination_in_the_library(text: str) -> None:
    frame = _LIBRARY(text)
    assert not frame.tasks, frame
    assert frame.question == "Where should I courier it to? Please give me the branch.", frame


@pytest.mark.parametrize(
    "text",
    [
        "courier my document to my solicitor",
        "courier my document to our publisher thanks",
        # fix129e's analogues and variants: a firm or the other party said by its role
        "courier my form to the supplier",
        "courier my contract to the other side's lawyers",
        "courier my contract to the other side’s solicitors pls",
        "courier my samples to the importer",
        "courier my invoice to the new customers",
        "courier my document to the shipping agent",
    ],
)
def test_a_role_is_no_destination_on_harbour(text: str) -> None:
    frame = _HARBOUR(text)
    assert not frame.tasks, frame
    assert frame.question == "Where should I courier it to? Please give me the address.", frame


@pytest.mark.parametrize(
    ("text", "where"),
    [
        # must not change: a place, an address, a place of the role
        ("courier my book to Westgate branch", "Westgate branch"),
        ("courier my book to the lawyer at 12 High Street", "the lawyer at 12 High Street"),
        ("courier my book to the client's office", "the client's office"),
        ("courier my book to the central library", "the central library"),
        ("courier my book to the supplier in Madrid", "the supplier in Madrid"),
        ("courier my book to the rowing club", "the rowing club"),
    ],
)
def test_a_place_or_an_address_is_sent_to(text: str, where: str) -> None:
    frame = _LIBRARY(text)
    assert frame.question is None, frame
    assert [(t.item, t.destination) for t in frame.tasks] == [("book", where)], frame


@pytest.mark.parametrize(
    ("text", "where"),
    [
        # must not change (fix129e's neighbours): a proper name, a place name, an address
        ("courier my form to Bodegas Ruiz in Madrid", "Bodegas Ruiz in Madrid"),
        ("courier my form to 12 High Street", "12 High Street"),
        (
            "courier my document to the Celestia at the Ocean Terminal",
            "the Celestia at the Ocean Terminal",
        ),
        ("courier my contract to the other side's office", "the other side's office"),
        ("courier my contract to the Leeds importer", "the Leeds importer"),
        ("courier my contract to the importer at 9 Dock Road", "the importer at 9 Dock Road"),
    ],
)
def test_a_name_or_an_address_is_sent_to_on_harbour(text: str, where: str) -> None:
    frame = _HARBOUR(text)
    assert frame.question is None, frame
    assert [t.destination for t in frame.tasks] == [where], frame


def test_an_address_after_a_role_is_sent_to_on_harbour() -> None:
    frame = _HARBOUR("courier my document to my solicitor at 4 Quay Street")
    assert frame.question is None, frame
    assert [t.destination for t in frame.tasks] == ["my solicitor at 4 Quay Street"], frame


@pytest.mark.parametrize(
    ("phrase", "role"),
    [
        ("my agent", True),
        ("my lawyer pls", True),
        ("our new accountant", True),
        ("Westgate branch", False),
        ("Agent Smith", False),
        ("the lawyer at 12 High Street", False),
        ("the client's office", False),
        ("the bank", False),
        ("the supplier", True),
        ("our lawyers", True),
        ("the other side's solicitors", True),
        ("the importer pls", True),
        ("the celestia", False),  # a word no dictionary has: a name said in lower case
        ("the supplier up north", False),
        ("the rowing club", False),
    ],
)
def test_names_only_a_role(phrase: str, role: bool) -> None:
    assert names_only_a_role(phrase) is role
