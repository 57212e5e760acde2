"""The office items the files of an inbound message are.

A messenger that knows the office (the simulator, the built-in one, whose REST callers name
items the resolver checked) gives each file its office item id. One that does not (Matrix)
names a file a person sent by the port's neutral ``file:<person>``
(``ports.messenger.persons_file``); in an office whose electronic type has another id
(``script``, ``drawing``) that is the sender's file as the office names it, so that a file
asked for is seen to have come (``script:lee``, not an unknown ``file:lee``).
"""

from __future__ import annotations

from assistantx.core.office import FILE_WORD, Office
from assistantx.core.ports.messenger import InboundMessage


def received_files(office: Office, message: InboundMessage) -> list[str]:
    """The item ids of the files ``message`` carries, in the office's names."""
    return [office_item(office, a.item) for a in message.attachments if a.item]


def office_item(office: Office, item: str) -> str:
    """``item`` in the office's names: the neutral ``file:<person>`` is that person's file,
    unless ``file`` is an item type of the office's own (then it is that)."""
    type_id, _, owner = item.partition(":")
    if type_id != FILE_WORD or not owner or office.file_type() is None:
        return item
    if any(t.id == FILE_WORD for t in office.item_types):
        return item
    return office.file_of(owner)
