"""The built-in messenger: people talk to the assistant through the REST API and the web page.

Every message, both ways, is kept in the journal, which is also the transcript the API serves.
An outbound message is journaled with its idempotency key *before* it is delivered and marked
sent after, so a resumed instruction that sends the same logical message again (same key) is
answered from the journal and nobody gets it twice. Inbound messages are deduplicated by event
id. Outbound messages can also be relayed elsewhere (the simulated colleagues read theirs
that way).
"""

from __future__ import annotations

import asyncio
import logging
import uuid
from collections.abc import Awaitable, Callable, Iterable
from datetime import UTC, datetime

from assistantx.core.clock import Clock
from assistantx.core.errors import MessengerError
from assistantx.core.ports.messenger import (
    Attachment,
    ChatRef,
    InboundMessage,
    Messenger,
    OutboundMessage,
    SentMessage,
)
from assistantx.store.journal import Journal, MessageRecord

logger = logging.getLogger(__name__)

ASSISTANT = "assistant"

Relay = Callable[[OutboundMessage], Awaitable[None]]
Listener = Callable[[MessageRecord], None]


class BuiltinMessenger(Messenger):
    platform = "builtin"

    def __init__(self, journal: Journal, clock: Clock) -> None:
        super().__init__()
        self._journal = journal
        self._clock = clock
        self._relays: list[Relay] = []
        self._listeners: list[Listener] = []
        self.duplicates_skipped = 0
        self.closed = False  # on shutdown: nothing more goes out (a resumed run sends it)

    def relay_to(self, relay: Relay) -> None:
        """Also hand every outbound message to ``relay`` (after journaling, before 'sent')."""
        self._relays.append(relay)

    def listen(self, listener: Listener) -> None:
        """Call ``listener`` with every new transcript entry (for live views)."""
        self._listeners.append(listener)

    async def send(self, message: OutboundMessage) -> SentMessage:
        if self.closed:
            raise MessengerError("the service is shutting down; the message was not sent")
        record = await self._journal.arecord_outbound(message, ASSISTANT, self._clock.now())
        if record.status == "sent":
            self.duplicates_skipped += 1
            logger.info("message %s was sent before; not sent again", message.idempotency_key)
            return self._sent(record)
        for relay in self._relays:
            try:
                await relay(message)
            except Exception as exc:
                raise MessengerError(f"could not deliver to {message.chat}: {exc}") from exc
        message_id = f"builtin-{record.seq}"
        await self._journal.amark_sent(record.seq, message_id)
        self._notify(record)
        return SentMessage(
            platform=self.platform,
            message_id=message_id,
            chat=message.chat,
            time=datetime.fromtimestamp(record.time, tz=UTC),
        )

    def accept(self, message: InboundMessage) -> MessageRecord | None:
        """Journal an inbound message and hand it to the assistant; None for a duplicate.

        Blocks until the journal has committed it: for callers that cannot await (the
        simulated colleagues' inbox); the service's routes use ``aaccept``."""
        return self._handed_on(message, self._journal.record_inbound(message))

    async def aaccept(self, message: InboundMessage) -> MessageRecord | None:
        """``accept``, awaited: the event loop runs on while the journal commits."""
        return self._handed_on(message, await self._journal.arecord_inbound(message))

    async def aaccept_many(self, messages: list[InboundMessage]) -> list[MessageRecord | None]:
        """``aaccept`` for several, in order: journaled together (one commit for the lot,
        not one round trip each), then handed on in the order given."""
        records = await asyncio.gather(*(self._journal.arecord_inbound(m) for m in messages))
        return [self._handed_on(m, r) for m, r in zip(messages, records, strict=True)]

    def _handed_on(
        self, message: InboundMessage, record: MessageRecord | None
    ) -> MessageRecord | None:
        if record is None:
            logger.info("duplicate inbound event %s ignored", message.event_id)
            return None
        if self._inbox is not None:
            self._inbox.put_nowait(message)
        self._notify(record)
        return record

    async def apost(
        self,
        sender: str,
        chat: ChatRef,
        text: str,
        *,
        in_reply_to: str | None = None,
        files: Iterable[str] = (),
        event_id: str | None = None,
    ) -> MessageRecord | None:
        """A person writes over REST or the web page."""
        return await self.aaccept(self._inbound(sender, chat, text, in_reply_to, files, event_id))

    def _inbound(
        self,
        sender: str,
        chat: ChatRef,
        text: str,
        in_reply_to: str | None,
        files: Iterable[str],
        event_id: str | None,
    ) -> InboundMessage:
        return InboundMessage(
            platform=self.platform,
            event_id=event_id or uuid.uuid4().hex,
            chat=chat,
            sender=sender,
            text=text,
            attachments=[Attachment(kind="file", name=f"{f}.pdf", item=f) for f in files],
            time=datetime.fromtimestamp(self._clock.now(), tz=UTC),
            in_reply_to=in_reply_to,
        )

    def _sent(self, record: MessageRecord) -> SentMessage:
        return SentMessage(
            platform=self.platform,
            message_id=record.message_id or f"builtin-{record.seq}",
            chat=record.chat,
            time=datetime.fromtimestamp(record.time, tz=UTC),
        )

    def _notify(self, record: MessageRecord) -> None:
        for listener in self._listeners:
            try:
                listener(record)
            except Exception:
                logger.exception("transcript listener failed")
