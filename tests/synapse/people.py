"""People of the office at their own Matrix client: a plain ``MatrixClient`` that /syncs,
joins the rooms its user is invited to, keeps what arrives (an ``Inbox``), and lets the test
answer."""

from __future__ import annotations

import asyncio
import itertools
import logging

from assistantx.adapters.messenger.matrix import MatrixClient
from helpers.qr import qr_text
from synapse.helpers import wait_joined
from synapse.homeserver import Account
from synapse.inbox import Inbox, Seen

logger = logging.getLogger(__name__)

_SYNC_TIMEOUT_MS = 500


class MatrixPerson(Inbox):
    def __init__(self, name: str, account: Account, homeserver_url: str) -> None:
        super().__init__(name)
        self.user_id = account.user_id
        self.client = MatrixClient(homeserver_url, account.access_token)
        self._txn = itertools.count(1)

    # -- the client's sync loop ------------------------------------------------------------

    async def start(self) -> None:
        # The first sync only takes the position: what happened before the test is not news.
        first = await self.client.sync(since=None, timeout_ms=0, filter_json=None)
        self._task = asyncio.create_task(self._run(str(first["next_batch"])), name=self.name)

    async def stop(self) -> None:
        await self.stop_syncing()
        await self.client.aclose()

    async def _run(self, since: str) -> None:
        while True:
            response = await self.client.sync(
                since=since, timeout_ms=_SYNC_TIMEOUT_MS, filter_json=None
            )
            since = str(response["next_batch"])
            rooms = response.get("rooms", {})
            for room_id in rooms.get("invite", {}):
                await self.client.join(room_id)  # people accept the assistant's DMs
            fresh = [
                Seen(room_id, e["event_id"], e["sender"], e.get("content", {}))
                for room_id, room in rooms.get("join", {}).items()
                for e in room.get("timeline", {}).get("events", [])
                if e.get("type") == "m.room.message" and e.get("sender") != self.user_id
            ]
            await self.add(fresh)

    # -- what a person does ----------------------------------------------------------------

    async def say(self, room_id: str, text: str) -> str:
        return await self.client.send_event(
            room_id,
            "m.room.message",
            {"msgtype": "m.text", "body": text},
            txn_id=f"{self.name}-{next(self._txn)}",
        )

    async def open_dm(self, user_id: str, *, also_wait_for: tuple[str, ...] = ()) -> str:
        """A direct chat with ``user_id``; returns once it (and ``also_wait_for``) joined."""
        room = await self.client.create_room(invite=[user_id], is_direct=True)
        for member in (user_id, *also_wait_for):
            await wait_joined(self.client, room, member)
        return room

    async def read_qr(self, image: Seen) -> str:
        """Download an image message and read the QR code in it, as a phone camera would."""
        assert image.msgtype == "m.image", image
        data = await self.client.download(str(image.content["url"]))
        return qr_text(data, image.body)
