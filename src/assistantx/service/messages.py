"""The built-in messenger over REST: people write to the assistant (or a group), and read the
journaled transcripts."""

from __future__ import annotations

from typing import Annotated, Literal

from fastapi import APIRouter, Query

from assistantx.core.ports.messenger import ChatRef
from assistantx.service.auth import Principal
from assistantx.service.deps import Caller, Runtime
from assistantx.service.errors import ForbiddenError, UnprocessableError
from assistantx.service.schemas import ChatOut, MessageIn, MessageOut
from assistantx.store.journal import MAX_SEQ

router = APIRouter(prefix="/v1", tags=["messages"])


@router.post("/messages", status_code=202, response_model=MessageOut)
async def post_message(body: MessageIn, runtime: Runtime, caller: Caller) -> MessageOut:
    """A person's message: a DM to the assistant (which may start an instruction or answer a
    question) or a message in a group chat they belong to."""
    sender: str
    if body.sender is not None:
        sender = runtime.resolver.person(body.sender)
        caller.require_person(sender)
    elif caller.person is not None:
        sender = caller.person
    else:
        raise UnprocessableError("the operator must name the 'sender' of a message")
    if body.group is not None:
        group = runtime.resolver.group(body.group)
        if sender not in runtime.office.group(group).members:
            raise ForbiddenError(f"{sender} is not a member of {group}")
        chat = ChatRef(kind="group", id=group)
    else:
        chat = ChatRef(kind="dm", id=sender)
    files = [runtime.resolver.item(f) for f in body.files]
    record = await runtime.messenger.apost(
        sender, chat, body.text, in_reply_to=body.in_reply_to, files=files
    )
    assert record is not None  # fresh event id: never a duplicate
    return MessageOut.of(record)


def _may_read(caller: Principal, chat: ChatRef, runtime: Runtime) -> bool:
    if caller.is_operator:
        return True
    if chat.kind == "dm":
        return chat.id == caller.person
    return caller.person in runtime.office.group(chat.id).members


@router.get("/chats", response_model=list[ChatOut])
async def list_chats(runtime: Runtime, caller: Caller) -> list[ChatOut]:
    """The chats with messages (a person sees their DM and their groups)."""
    return [
        ChatOut(kind=c.chat.kind, id=c.chat.id, messages=c.messages, last_time=c.last_time)
        for c in runtime.journal.chats()
        if _may_read(caller, c.chat, runtime)
    ]


@router.get("/chats/{kind}/{chat_id}", response_model=list[MessageOut])
async def get_chat(
    kind: Literal["dm", "group"],
    chat_id: str,
    runtime: Runtime,
    caller: Caller,
    after: Annotated[int, Query(ge=0, le=MAX_SEQ)] = 0,
    limit: Annotated[int, Query(ge=1, le=500)] = 200,
) -> list[MessageOut]:
    """One chat's transcript, oldest first, after the message sequence number ``after``."""
    resolved = runtime.resolver.person(chat_id) if kind == "dm" else runtime.resolver.group(chat_id)
    chat = ChatRef(kind=kind, id=resolved)
    if not _may_read(caller, chat, runtime):
        raise ForbiddenError(f"you may not read {chat}")
    records = runtime.journal.messages(chat, after_seq=after, limit=limit)
    return [MessageOut.of(r) for r in records]
