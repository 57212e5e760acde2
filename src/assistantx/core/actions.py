"""The action space (DESIGN §3): the contract between Decision and the executors.

Actions are a pydantic discriminated union on ``type``; ``action_json_schema()`` is what a
model is given. Arguments name people, groups, places and items by name or id; grounding
(``assistantx.memory.resolve``) turns them into ids or fails with a message for the model.
"""

from __future__ import annotations

from typing import Annotated, Any, Literal

from pydantic import BaseModel, ConfigDict, Field, TypeAdapter

from assistantx.core.ports.lock import Purpose

ActionKind = Literal["cyber", "real", "generic"]
Outcome = Literal["done", "failed", "unachievable"]


class _Action(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)

    @property
    def kind(self) -> ActionKind:
        raise NotImplementedError

    def signature(self) -> str:
        """A canonical text of the action, used to detect repetitions."""
        fields = self.model_dump(exclude={"type"})
        args = ", ".join(f"{k}={v!r}" for k, v in sorted(fields.items()))
        return f"{self.type}({args})"  # type: ignore[attr-defined]

    def targets(self) -> tuple[str, ...]:
        """The people or groups this action reaches (for availability and relevance)."""
        return ()


class Inform(_Action):
    """Send a message to a person or a group chat."""

    type: Literal["inform"] = "inform"
    contact: str = Field(description="person or group chat")
    content: str = Field(min_length=1, max_length=2000)

    @property
    def kind(self) -> ActionKind:
        return "cyber"

    def targets(self) -> tuple[str, ...]:
        return (self.contact,)


class Inquire(_Action):
    """Ask a person or a group chat a question; the reply arrives in the dialogue."""

    type: Literal["inquire"] = "inquire"
    contact: str = Field(description="person or group chat")
    question: str = Field(min_length=1, max_length=2000)

    @property
    def kind(self) -> ActionKind:
        return "cyber"

    def targets(self) -> tuple[str, ...]:
        return (self.contact,)


class ForwardFile(_Action):
    """Forward an electronic file received from ``source`` to ``target``."""

    type: Literal["forward_file"] = "forward_file"
    source: str = Field(description="the person the file came from")
    target: str = Field(description="person or group chat to forward it to")
    file: str | None = Field(default=None, description="file item id; default: source's file")

    @property
    def kind(self) -> ActionKind:
        return "cyber"

    def targets(self) -> tuple[str, ...]:
        return (self.target,)


class SendQR(_Action):
    """Send a person a one-time QR code that opens the locker for one purpose."""

    type: Literal["send_qr"] = "send_qr"
    contact: str = Field(description="the person who will scan it")
    item: str = Field(description="the item concerned, e.g. 'stapler:zhang' or \"Zhang's stapler\"")
    purpose: Purpose = Field(
        default="deposit",
        description="deposit: put the item in; collect: take it out; sign/seal/copy/heat: take "
        "it out, do that, put it back; produce: make it at a facility and put it in",
    )
    operation: str | None = Field(
        default=None,
        description="the office operation a work step runs, when a facility offers several of "
        "its shape (copy and scan at one machine): the code's text names it",
    )
    destination: str | None = Field(
        default=None,
        description="where an operation that sends the item outside sends it, in the "
        "requester's words ('the county tax office'): the code's text names it",
    )
    send_to: str | None = Field(
        default=None,
        description="the person (id) a file the work makes (a scan to PDF) is sent to by "
        "message, when not the item's owner: the code's text names them",
    )

    @property
    def kind(self) -> ActionKind:
        return "cyber"

    def targets(self) -> tuple[str, ...]:
        return (self.contact,)


class Wait(_Action):
    """Wait for an online reply; ends on the reply or the timeout."""

    type: Literal["wait"] = "wait"
    reason: str = Field(default="waiting for a reply", max_length=500)
    timeout_s: float = Field(default=120.0, ge=1.0, le=3600.0)

    @property
    def kind(self) -> ActionKind:
        return "cyber"


class Move(_Action):
    """Drive to a place: a person's name (their desk), a facility or a location."""

    type: Literal["move"] = "move"
    place: str

    @property
    def kind(self) -> ActionKind:
        return "real"


class WaitInPlace(_Action):
    """Wait at the current place for a physical hand-over at the locker."""

    type: Literal["wait_in_place"] = "wait_in_place"
    person: str
    timeout_s: float = Field(default=300.0, ge=1.0, le=3600.0)

    @property
    def kind(self) -> ActionKind:
        return "real"

    def targets(self) -> tuple[str, ...]:
        return (self.person,)


class Stop(_Action):
    """End the instruction; the requester is told the outcome and the summary."""

    type: Literal["stop"] = "stop"
    outcome: Outcome
    summary: str = Field(min_length=1, max_length=2000)

    @property
    def kind(self) -> ActionKind:
        return "generic"


Action = Annotated[
    Inform | Inquire | ForwardFile | SendQR | Wait | Move | WaitInPlace | Stop,
    Field(discriminator="type"),
]
ACTION_TYPES = (Inform, Inquire, ForwardFile, SendQR, Wait, Move, WaitInPlace, Stop)

_action_adapter: TypeAdapter[Action] = TypeAdapter(Action)
_action_list_adapter: TypeAdapter[list[Action]] = TypeAdapter(list[Action])


def parse_action(data: Any) -> Action:
    """Validate one action from JSON-like data (raises pydantic.ValidationError)."""
    return _action_adapter.validate_python(data)


def parse_actions(data: Any) -> list[Action]:
    return _action_list_adapter.validate_python(data)


def action_json_schema() -> dict[str, Any]:
    """The JSON schema of one action, to give to a model."""
    return _action_adapter.json_schema()
