"""The assistant writes on a real Synapse: DMs, group rooms, QR images, forwarded files."""

from __future__ import annotations

import asyncio
import io
import uuid
from collections.abc import Callable
from pathlib import Path

import pytest
import segno

from assistantx.adapters.messenger.matrix import (
    MatrixClient,
    MatrixConfig,
    MatrixMessenger,
    SqliteEventStore,
)
from assistantx.core.ports.messenger import Attachment, ChatRef, InboundMessage, OutboundMessage
from synapse.gateway import AppserviceGateway
from synapse.helpers import (
    Colleague,
    bridge,
    derive,
    dm_with,
    join_when_invited,
    next_message,
    room_messages,
    wait_room_messages,
)
from synapse.homeserver import Account

pytestmark = [pytest.mark.synapse, pytest.mark.asyncio(loop_scope="session")]


def qr_png(payload: str) -> bytes:
    buffer = io.BytesIO()
    segno.make(payload, error="m").save(buffer, kind="png", scale=4)
    return buffer.getvalue()


async def test_text_to_a_dm_and_to_a_group_room(
    base_config: MatrixConfig,
    new_account: Callable[[str], Account],
    tmp_path: Path,
) -> None:
    lee, zhang = new_account("lee"), new_account("zhang")
    alias_local = f"printing-{uuid.uuid4().hex[:6]}"
    async with (
        MatrixClient(base_config.homeserver_url, lee.access_token) as lee_client,
        MatrixClient(base_config.homeserver_url, zhang.access_token) as zhang_client,
    ):
        group_room = await zhang_client.create_room(
            preset="public_chat", alias_localpart=alias_local
        )
        config = derive(
            base_config,
            people={"lee": lee.user_id, "zhang": zhang.user_id},
            groups={"printing": f"#{alias_local}:{base_config.server_name}"},
        )
        async with MatrixMessenger(config, SqliteEventStore(tmp_path / "e.db")) as messenger:
            sent_dm = await messenger.send(
                OutboundMessage(
                    chat=ChatRef(kind="dm", id="lee"),
                    text="Your parcel is here",
                    idempotency_key="k-dm",
                )
            )
            dm_room = await messenger.dm_room("lee")
            # A retry of the same logical message posts nothing new.
            again = await messenger.send(
                OutboundMessage(
                    chat=ChatRef(kind="dm", id="lee"),
                    text="Your parcel is here",
                    idempotency_key="k-dm",
                )
            )
            assert again.message_id == sent_dm.message_id
            await join_when_invited(lee_client, dm_room)
            events = await room_messages(lee_client, dm_room)
            assert [(e["sender"], e["content"]["body"]) for e in events] == [
                (config.bot_user_id, "Your parcel is here")
            ]
            assert events[0]["event_id"] == sent_dm.message_id
            # The room is recorded as the DM with lee in the bot's m.direct.
            async with MatrixClient(
                config.homeserver_url, config.as_token.get_secret_value()
            ) as bot:
                direct = await bot.get_account_data(config.bot_user_id, "m.direct")
            assert direct is not None and dm_room in direct[lee.user_id]
            assert await messenger.dm_room("lee") == dm_room  # found again, not re-created

            sent_group = await messenger.send(
                OutboundMessage(
                    chat=ChatRef(kind="group", id="printing"),
                    text="Who can sign a form?",
                    idempotency_key="k-group",
                )
            )
            assert sent_group.chat == ChatRef(kind="group", id="printing")
            group_events = await wait_room_messages(zhang_client, group_room, 1)
            assert [e["content"]["body"] for e in group_events] == ["Who can sign a form?"]


async def test_qr_code_arrives_as_an_image_in_the_right_room(
    lee: Colleague,
    lee_config: MatrixConfig,
    new_account: Callable[[str], Account],
    event_store: SqliteEventStore,
) -> None:
    wang = new_account("wang")
    config = derive(lee_config, people={**lee_config.people, "wang": wang.user_id})
    png = qr_png("locker-7:open:task-42")
    lee_client = lee.client
    async with MatrixMessenger(config, event_store) as messenger:
        await messenger.send(
            OutboundMessage(chat=ChatRef(kind="dm", id="wang"), text="not for lee")
        )
        await messenger.send(
            OutboundMessage(
                chat=ChatRef(kind="dm", id="lee"),
                text="Scan this at the locker",
                attachments=[
                    Attachment(kind="image", name="locker-code.png", mime="image/png", data=png)
                ],
                idempotency_key="qr-1",
            )
        )
        room = await messenger.dm_room("lee")
        assert room != await messenger.dm_room("wang")
        await join_when_invited(lee_client, room)
        events = await room_messages(lee_client, room)
        assert [e["content"]["msgtype"] for e in events] == ["m.text", "m.image"]
        image = events[1]["content"]
        assert image["info"]["mimetype"] == "image/png"
        assert image["info"]["size"] == len(png)
        assert image["info"]["w"] == image["info"]["h"] > 0
        assert await lee_client.download(image["url"]) == png


async def test_a_received_file_is_forwarded_by_its_uri(
    lee: Colleague,
    lee_config: MatrixConfig,
    gateway_mounts: AppserviceGateway,
    new_account: Callable[[str], Account],
    event_store: SqliteEventStore,
    inbox: asyncio.Queue[InboundMessage],
) -> None:
    zhang = new_account("zhang")
    config = derive(lee_config, people={**lee_config.people, "zhang": zhang.user_id})
    messenger = bridge(config, event_store, inbox, gateway_mounts)
    report = b"%PDF-1.4 quarterly report\n" * 40
    lee_client = lee.client
    async with (
        messenger,
        MatrixClient(config.homeserver_url, zhang.access_token) as zhang_client,
    ):
        room = await dm_with(lee_client, config.bot_user_id)
        url = await lee_client.upload(report, content_type="application/pdf", filename="report.pdf")
        await lee_client.send_event(
            room,
            "m.room.message",
            {
                "msgtype": "m.file",
                "body": "report.pdf",
                "url": url,
                "info": {"mimetype": "application/pdf", "size": len(report)},
            },
            txn_id="f1",
        )
        received = await next_message(inbox)
        assert received.attachments[0].model_dump() == {
            "kind": "file",
            "name": "report.pdf",
            "mime": "application/pdf",
            "ref": url,
            "item": "file:lee",  # the office's name for Lee's file, so forward_file finds it
        }
        await messenger.send(
            OutboundMessage(
                chat=ChatRef(kind="dm", id="zhang"),
                text="From Lee",
                attachments=received.attachments,
                idempotency_key="fwd-1",
            )
        )
        zhang_room = await messenger.dm_room("zhang")
        await join_when_invited(zhang_client, zhang_room)
        events = await room_messages(zhang_client, zhang_room)
        forwarded = events[-1]["content"]
        assert (forwarded["msgtype"], forwarded["url"], forwarded["body"]) == (
            "m.file",
            url,
            "report.pdf",
        )
        assert await zhang_client.download(forwarded["url"]) == report
