"""Request and response bodies of the REST API. Requests forbid unknown fields."""

from __future__ import annotations

import unicodedata
from typing import Annotated, Any, Literal

from pydantic import AfterValidator, BaseModel, ConfigDict, Field

from assistantx.store.journal import InstructionRecord, MessageRecord, Status

Id = Field(min_length=1, max_length=100, pattern=r"^[A-Za-z0-9_.:\- ]+$")


def _visible_text(value: str) -> str:
    """Words a person wrote: no NUL (it ends strings in C code and terminals downstream) and
    at least one visible character."""
    if "\x00" in value:
        raise ValueError("text must not contain NUL characters")
    if not any(ch.isprintable() and not ch.isspace() for ch in value):
        raise ValueError("text must contain a visible character")
    return value


def _no_control_characters(value: str) -> str:
    """A name or id: control characters would forge log lines and break transcripts."""
    if any(unicodedata.category(ch) == "Cc" for ch in value):
        raise ValueError("must not contain control characters")
    return value


Text = Annotated[str, AfterValidator(_visible_text)]
Name = Annotated[str, AfterValidator(_no_control_characters)]


class _Request(BaseModel):
    model_config = ConfigDict(extra="forbid", str_strip_whitespace=True)


class InstructionIn(_Request):
    """An instruction from a person, in their own words, as a JSON object."""

    model_config = ConfigDict(
        json_schema_extra={"examples": [{"requester": "lee", "text": "Bring me a stapler"}]}
    )

    requester: Name = Field(
        min_length=1,
        max_length=100,
        description="who asks: a person's id or name as people write it, e.g. lee or Lee Ming",
        examples=["lee"],
    )
    text: Text = Field(
        min_length=1,
        max_length=4000,
        description="the instruction in words, at most 4000 characters",
        examples=["Bring me a stapler"],
    )


class InstructionOut(BaseModel):
    id: str
    requester: str
    text: str
    status: Status
    outcome: str | None
    summary: str | None
    created_at: float
    updated_at: float
    steps: int = Field(default=0, description="steps begun so far")
    links: dict[str, str]

    @classmethod
    def of(cls, record: InstructionRecord) -> InstructionOut:
        base = f"/v1/instructions/{record.id}"
        return cls(
            id=record.id,
            requester=record.requester,
            text=record.text,
            status=record.status,
            outcome=record.outcome,
            summary=record.summary,
            created_at=record.created_at,
            updated_at=record.updated_at,
            steps=len(record.stm.trace.steps) if record.stm else record.steps,
            links={"self": base, "events": f"{base}/events", "cancel": f"{base}/cancel"},
        )


class InstructionDetail(InstructionOut):
    trace: dict[str, Any] | None = None
    dialogue: list[dict[str, Any]] = Field(default_factory=list)

    @classmethod
    def full(cls, record: InstructionRecord) -> InstructionDetail:
        out = cls.of(record).model_dump()
        if record.stm is not None:
            out["trace"] = record.stm.trace.model_dump(mode="json")
            out["dialogue"] = [t.model_dump(mode="json") for t in record.stm.dialogue]
        return cls.model_validate(out)


class InstructionPage(BaseModel):
    items: list[InstructionOut]
    next_cursor: str | None = Field(description="pass as ?cursor= for the next page")


class CancelOut(BaseModel):
    id: str
    cancelled: bool = Field(description="False when the instruction had already ended")
    status: Status


class MessageIn(_Request):
    """A chat message to the assistant (a DM, or a group chat with ``group``)."""

    model_config = ConfigDict(
        json_schema_extra={"examples": [{"text": "Yes, I have one", "in_reply_to": "q-1"}]}
    )

    text: Text = Field(min_length=1, max_length=4000)
    group: Name | None = Field(default=None, max_length=100, description="group chat id; else DM")
    in_reply_to: Name | None = Field(default=None, max_length=200, description="question id")
    sender: Name | None = Field(default=None, max_length=100, description="operator only")
    files: list[str] = Field(default_factory=list, max_length=10, description="file item ids")


class MessageOut(BaseModel):
    seq: int
    direction: Literal["in", "out"]
    chat: dict[str, str]
    sender: str
    text: str
    time: float
    instruction_id: str | None
    question_id: str | None
    in_reply_to: str | None
    status: str
    attachments: list[dict[str, Any]] = Field(default_factory=list)

    @classmethod
    def of(cls, r: MessageRecord) -> MessageOut:
        return cls(
            seq=r.seq,
            direction=r.direction,
            chat={"kind": r.chat.kind, "id": r.chat.id},
            sender=r.sender,
            text=r.text,
            time=r.time,
            instruction_id=r.instruction_id,
            question_id=r.question_id,
            in_reply_to=r.in_reply_to,
            status=r.status,
            attachments=list(r.body.get("attachments", [])),
        )


class ChatOut(BaseModel):
    kind: Literal["dm", "group"]
    id: str
    messages: int
    last_time: float


class PersonPatch(_Request):
    available: bool | None = Field(
        default=None, description="true/false; null resets to unknown (send the key to set it)"
    )
    location: str | None = Field(default=None, max_length=100, description="a location id")
    evidence: str = Field(default="set by the operator", min_length=1, max_length=500)


class PersonOut(BaseModel):
    id: str
    name: str
    available: str
    observed_at: float | None
    location: str
    items: list[str]
    groups: list[str]
