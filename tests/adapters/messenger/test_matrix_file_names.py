"""A file a person sent over Matrix is found again by the office's name for it (issue 23):
the adapter cannot know that the office calls its files scripts, so it keeps a file as the
sender's ``file:lee``; the runtime forwards it as ``script:lee``."""

from __future__ import annotations

import pytest

from assistantx.adapters.messenger.matrix import MatrixConfig, SqliteEventStore
from assistantx.adapters.messenger.matrix.adapter import MatrixMessenger
from assistantx.core.errors import MessengerError
from assistantx.core.ports.messenger import Attachment, persons_file


def _messenger(store: SqliteEventStore) -> MatrixMessenger:
    config = MatrixConfig(
        homeserver_url="http://127.0.0.1:8008",
        server_name="office.test",
        as_token="as-token",
        hs_token="hs-token",
        people={"lee": "@lee:office.test", "zhang": "@zhang:office.test"},
    )
    return MatrixMessenger(config, store)


@pytest.mark.parametrize("item", ["file:lee", "script:lee", "drawing:lee"])
async def test_the_senders_file_is_found_by_any_name_of_the_office(
    store: SqliteEventStore, item: str
) -> None:
    await store.remember_media(persons_file("lee"), "mxc://o/1", "act1.pdf", "application/pdf")
    content = await _messenger(store)._describe(
        Attachment(kind="file", name="script.pdf", item=item)
    )
    assert (content["url"], content["filename"]) == ("mxc://o/1", "act1.pdf")


async def test_someone_elses_file_is_not_theirs(store: SqliteEventStore) -> None:
    await store.remember_media(persons_file("lee"), "mxc://o/1", "act1.pdf", "application/pdf")
    with pytest.raises(MessengerError, match="zhang has not sent it"):
        await _messenger(store)._describe(
            Attachment(kind="file", name="script.pdf", item="script:zhang")
        )
