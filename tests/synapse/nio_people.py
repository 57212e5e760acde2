"""People of the office at a Matrix client nobody here wrote: ``matrix-nio``'s ``AsyncClient``.

Each person syncs in the background, accepts the invites they get (as people accept the
assistant's DMs), and keeps every event others send to rooms they are in. ``expect`` hands out
each received message once (oldest first among those that match), so a test reads a
conversation the way a person does.
"""

from __future__ import annotations

import asyncio
import io
import logging
from collections.abc import Callable
from typing import Any

import httpx
from nio import (
    AsyncClient,
    AsyncClientConfig,
    JoinedMembersResponse,
    ReceiptEvent,
    RoomCreateResponse,
    RoomSendResponse,
    SyncResponse,
    TypingNoticeEvent,
    UploadResponse,
)

from helpers.eventually import eventually
from helpers.qr import qr_text
from synapse.helpers import WAIT_S
from synapse.homeserver import Account
from synapse.inbox import Inbox, Seen

logger = logging.getLogger(__name__)

ENCRYPTION = {"algorithm": "m.megolm.v1.aes-sha2"}


class NioPerson(Inbox):
    def __init__(self, name: str, account: Account, homeserver_url: str) -> None:
        super().__init__(name)
        self.user_id = account.user_id
        self.client = AsyncClient(
            homeserver_url,
            account.user_id,
            config=AsyncClientConfig(encryption_enabled=False, store_sync_tokens=False),
        )
        self.client.access_token = account.access_token
        self.client.user_id = account.user_id
        self.auto_join = True
        # Messages a test reads apart (the feedback survey after each instruction).
        self.aside: Callable[[Seen], bool] = lambda m: False
        # What others showed in the rooms: ("typing", room, user) and ("read", room, user,
        # event id), in arrival order.
        self.signals: list[tuple[str, ...]] = []

    async def start(self) -> None:
        first = await self.client.sync(timeout=0)
        assert isinstance(first, SyncResponse), first
        self._task = asyncio.create_task(self._run(), name=f"nio-{self.name}")

    async def stop(self) -> None:
        await self.stop_syncing()
        await self.client.close()

    async def _run(self) -> None:
        while True:
            response = await self.client.sync(timeout=300, since=self.client.next_batch)
            if not isinstance(response, SyncResponse):
                await asyncio.sleep(0.2)
                continue
            if self.auto_join:
                for room_id in response.rooms.invite:
                    await self.client.join(room_id)
            for room_id, room in response.rooms.join.items():
                for signal in room.ephemeral:
                    if isinstance(signal, TypingNoticeEvent):
                        self.signals += [("typing", room_id, user) for user in signal.users]
                    elif isinstance(signal, ReceiptEvent):
                        self.signals += [
                            ("read", room_id, r.user_id, r.event_id) for r in signal.receipts
                        ]
            fresh = [
                Seen(
                    room_id,
                    str(event.source["event_id"]),
                    str(event.source["sender"]),
                    dict(event.source.get("content", {})),
                    str(event.source.get("type")),
                )
                for room_id, room in response.rooms.join.items()
                for event in room.timeline.events
                if event.source.get("sender") != self.user_id
                and event.source.get("type") in ("m.room.message", "m.reaction")
            ]
            await self.add(fresh)

    # -- reading ---------------------------------------------------------------------------
    def visible(self, message: Seen) -> bool:
        return super().visible(message) and not self.aside(message)

    def set_aside(self) -> list[Seen]:
        return [m for m in self.seen if m.type == "m.room.message" and self.aside(m)]

    def from_(self, sender: str) -> list[Seen]:
        return self.messages(lambda m: m.sender == sender)

    # -- acting ----------------------------------------------------------------------------
    async def send(
        self, room_id: str, content: dict[str, Any], kind: str = "m.room.message"
    ) -> str:
        response = await self.client.room_send(room_id, kind, content)
        assert isinstance(response, RoomSendResponse), response
        return str(response.event_id)

    async def say(self, room_id: str, text: str, **extra: Any) -> str:
        return await self.send(room_id, {"msgtype": "m.text", "body": text, **extra})

    async def react(self, room_id: str, event_id: str, key: str) -> str:
        relates = {"rel_type": "m.annotation", "event_id": event_id, "key": key}
        return await self.send(room_id, {"m.relates_to": relates}, kind="m.reaction")

    async def upload_file(self, room_id: str, name: str, data: bytes, caption: str = "") -> str:
        """Upload ``data`` and post it as an m.file (with ``caption`` as its body, if any)."""
        response, _keys = await self.client.upload(
            io.BytesIO(data), content_type="application/pdf", filename=name, filesize=len(data)
        )
        assert isinstance(response, UploadResponse), response
        content: dict[str, Any] = {
            "msgtype": "m.file",
            "body": caption or name,
            "filename": name,
            "url": response.content_uri,
            "info": {"mimetype": "application/pdf", "size": len(data)},
        }
        await self.send(room_id, content)
        return str(response.content_uri)

    async def create_room(
        self,
        invite: list[str],
        *,
        is_direct: bool = False,
        alias: str | None = None,
        encrypted: bool = False,
    ) -> str:
        """A room; ``encrypted``: with end-to-end encryption on from the start (as Element
        creates DMs by default)."""
        state = [{"type": "m.room.encryption", "state_key": "", "content": ENCRYPTION}]
        response = await self.client.room_create(
            invite=invite,
            is_direct=is_direct,
            alias=alias,
            name=None,
            initial_state=state if encrypted else (),
        )
        assert isinstance(response, RoomCreateResponse), response
        return str(response.room_id)

    async def open_dm(self, user_id: str, *, also: tuple[str, ...] = ()) -> str:
        """A direct chat with ``user_id``; returns once it (and ``also``) joined."""
        room = await self.create_room([user_id, *also], is_direct=True)
        for member in (user_id, *also):
            await self.wait_member(room, member)
        return room

    async def members(self, room_id: str) -> set[str]:
        response = await self.client.joined_members(room_id)
        if not isinstance(response, JoinedMembersResponse):
            return set()
        return {m.user_id for m in response.members}

    async def wait_member(self, room_id: str, user_id: str, *, present: bool = True) -> None:
        async def settled() -> bool:
            return (user_id in await self.members(room_id)) == present

        state = "in" if present else "out of"
        await eventually(
            settled, what=f"{user_id} to be {state} {room_id}", timeout_s=WAIT_S, interval_s=0.1
        )

    async def download(self, mxc: str) -> bytes:
        # nio's download uses the legacy unauthenticated media path, which Synapse has
        # frozen; clients today use the authenticated one.
        server, media_id = mxc.removeprefix("mxc://").split("/")
        async with httpx.AsyncClient(base_url=self.client.homeserver) as http:
            response = await http.get(
                f"/_matrix/client/v1/media/download/{server}/{media_id}",
                headers={"Authorization": f"Bearer {self.client.access_token}"},
            )
        response.raise_for_status()
        return response.content

    async def read_qr(self, image: Seen) -> str:
        assert image.msgtype == "m.image", image
        data = await self.download(str(image.content["url"]))
        return qr_text(data, image.body)
