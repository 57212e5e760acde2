"""The messenger interface: text, images and files to people and group chats, and inbound
messages normalized to one shape whatever the platform.

Implementations: the simulator (simulated people), the built-in messenger of the service
(REST + web page), Matrix. Inbound messages go onto the one ``asyncio.Queue`` connected with
``connect_inbox``; one consumer dispatches them.
"""

from __future__ import annotations

import asyncio
from abc import ABC, abstractmethod
from datetime import datetime
from typing import Literal

from pydantic import BaseModel, Field

from assistantx.core.lifecycle import Component
from assistantx.core.office import FILE_WORD


class ChatRef(BaseModel):
    """A conversation: a DM with a person (id = person id) or a group chat (id = group id)."""

    model_config = {"frozen": True}

    kind: Literal["dm", "group"]
    id: str

    def __str__(self) -> str:
        return f"{self.kind}:{self.id}"


def persons_file(person: str) -> str:
    """What a messenger that cannot know the office (Matrix) calls a file ``person`` sent:
    ``file:<person>``. The runtime reads it as the office's own name for that person's file
    (``script:lee`` in an office whose electronic type is a script: ``Office.file_of``)."""
    return f"{FILE_WORD}:{person}"


class Attachment(BaseModel):
    kind: Literal["image", "file"]
    name: str
    mime: str = "application/octet-stream"
    data: bytes | None = Field(default=None, exclude=True)
    ref: str | None = Field(default=None, description="platform media reference, e.g. mxc://")
    item: str | None = Field(default=None, description="office item id, e.g. file:lee")
    qr_payload: str | None = Field(
        default=None, exclude=True, description="the text a QR image encodes (for simulators)"
    )
    qr_purpose: str | None = Field(
        default=None, exclude=True, description="what the QR code is for (for simulators)"
    )


class OutboundMessage(BaseModel):
    chat: ChatRef
    text: str
    attachments: list[Attachment] = Field(default_factory=list)
    instruction_id: str | None = None
    question_id: str | None = Field(default=None, description="set when a reply is expected")
    idempotency_key: str | None = Field(
        default=None, description="stable per logical message, so retries never duplicate"
    )


class SentMessage(BaseModel):
    platform: str
    message_id: str
    chat: ChatRef
    time: datetime


class InboundMessage(BaseModel):
    platform: str
    event_id: str
    chat: ChatRef
    sender: str = Field(description="person id of the author")
    text: str
    attachments: list[Attachment] = Field(default_factory=list)
    time: datetime
    in_reply_to: str | None = Field(default=None, description="question id, where known")


class Messenger(Component, ABC):
    """Sends to people and groups; delivers what they write to the connected inbox. Started and
    stopped as a ``Component`` (connect in ``_start``, disconnect in ``_stop``)."""

    platform: str = "abstract"

    def __init__(self) -> None:
        super().__init__()
        self._inbox: asyncio.Queue[InboundMessage] | None = None

    def connect_inbox(self, inbox: asyncio.Queue[InboundMessage]) -> None:
        self._inbox = inbox

    async def _deliver(self, message: InboundMessage) -> None:
        if self._inbox is not None:
            await self._inbox.put(message)

    async def acknowledge(self, message: InboundMessage) -> None:
        """The consumer is done with ``message``; a durable messenger stops replaying it."""

    @abstractmethod
    async def send(self, message: OutboundMessage) -> SentMessage:
        """Deliver ``message`` once (retries with the same idempotency key never duplicate)."""
