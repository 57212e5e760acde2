"""The files of an inbound message in the office's names (issue 23): a messenger that knows
no office labels a file a person sent ``file:<person>``; in an office whose electronic type
is a ``script`` that is the sender's script."""

from __future__ import annotations

from datetime import UTC, datetime

import pytest

from assistantx.core.office import Office, load_office, parse_office
from assistantx.core.ports.messenger import Attachment, ChatRef, InboundMessage, persons_file
from assistantx.runtime.received_files import office_item, received_files
from helpers.rehearsal_rooms import (
    drafting_studio,
    raw_rehearsal_rooms,
    rehearsal_rooms,
    rehearsal_rooms_without_files,
)


def _message(sender: str, *items: str) -> InboundMessage:
    return InboundMessage(
        platform="matrix",
        event_id="$e",
        chat=ChatRef(kind="dm", id=sender),
        sender=sender,
        text="here it is",
        attachments=[Attachment(kind="file", name=f"{i}.pdf", item=i) for i in items],
        time=datetime(2026, 1, 1, tzinfo=UTC),
    )


@pytest.mark.parametrize(
    ("office", "expected"),
    [
        (rehearsal_rooms(), "script:bruno"),
        (drafting_studio(), "drawing:bruno"),
        (load_office(), "file:bruno"),
    ],
    ids=["script", "drawing", "default"],
)
def test_the_neutral_name_is_the_senders_file_as_the_office_names_it(
    office: Office, expected: str
) -> None:
    assert office_item(office, persons_file("bruno")) == expected


def test_an_office_item_is_kept() -> None:
    office = rehearsal_rooms()
    assert office_item(office, "script:kwesi") == "script:kwesi"
    assert office_item(office, "contract:kwesi") == "contract:kwesi"
    assert received_files(office, _message("bruno", "file:bruno", "script:kwesi")) == [
        "script:bruno",
        "script:kwesi",
    ]


def test_an_office_whose_own_type_is_called_file_keeps_it() -> None:
    """A paper ``file`` (a folder) beside the electronic ``script``: ``file:bruno`` named by
    the office is Bruno's folder, not his script."""
    raw = raw_rehearsal_rooms()
    raw["item_types"].append({"id": "file", "name": "folder"})
    office = parse_office(raw, "with_folders")
    assert office_item(office, "file:bruno") == "file:bruno"


def test_an_office_with_no_files_keeps_the_name() -> None:
    assert office_item(rehearsal_rooms_without_files(), "file:bruno") == "file:bruno"
