"""The task schema: what a request means, the one contract between understanding and planning.

A request is understood into a :class:`TaskFrame`: the tasks to do (each a :class:`Task`), or
one question for the requester, or a refusal (``decline``) that does nothing and says why.
Whatever reads a request (the embedded parser, the LLM understanding path) produces a frame;
whatever acts on one (the planner, the simulator's people, the evaluator) reads only the frame.

Beside the tasks a frame carries what the requester *told* rather than asked (``hints``:
"Wang is away", "Zhang is in the meeting room", "Zhang's stapler is broken"), which is memory
for the planner and never makes that person a party, and the ``evidence``: which words gave
which reading, in words a person can read, for the trace.

This module sits in the domain core (below memory and the agents) and imports nothing of
them.
"""

from __future__ import annotations

from typing import Literal

from pydantic import BaseModel, ConfigDict, Field

from assistantx.office import Office, OperationShape

# The shapes of a task. ``transfer``: a physical item moves from its owner (or a keeper) to
# the recipient; ``produce``: a facility makes a product for the recipient; ``print``/``copy``:
# a facility turns the requester's file/document into a product; ``sign``/``seal``: a person
# acts on the requester's document; ``heat``: a facility works on a kept item; ``send_file``:
# an electronic file is forwarded.
TaskKind = Literal["transfer", "print", "copy", "sign", "seal", "produce", "heat", "send_file"]
# The tool of a ``seal`` task: anyone who owns an item of this type can stamp a document.
SEAL_TOOL = "seal"
# The task kind each shape of office operation takes (office.Operation.shape).
SHAPE_KIND: dict[OperationShape, TaskKind] = {
    "make": "produce",
    "render": "print",
    "transform": "copy",
    "treat": "heat",
}
HintKind = Literal["availability", "location", "condition"]
DeclineOutcome = Literal["done", "unachievable"]


class Task(BaseModel):
    """One thing to get done."""

    model_config = ConfigDict(frozen=True)

    kind: TaskKind
    item: str | None = Field(default=None, description="item type id (a product for produce)")
    owner: str | None = Field(default=None, description="whose item; None = anyone's")
    recipient: str = Field(description="who ends up with the result")
    actor: str | None = Field(default=None, description="who must do it (signer, named helper)")
    operation: str | None = Field(
        default=None, description="the office's operation (print, copy, heat, produce kinds)"
    )

    def item_id(self) -> str | None:
        """The concrete item, when the frame fixes it (``stapler:zhang``, ``coffee:lee``)."""
        if self.item is None:
            return None
        if self.kind == "produce":
            return f"{self.item}:{self.recipient}"
        if self.kind == "print":
            return f"file:{self.owner}"
        return f"{self.item}:{self.owner}" if self.owner else None


class Hint(BaseModel):
    """A fact the requester stated, for memory: never a request, never a party to one."""

    model_config = ConfigDict(frozen=True)

    kind: HintKind
    person: str
    value: str = Field(description="'away'/'here', a location id, or a condition word")
    item_type: str | None = Field(default=None, description="the item a condition is about")
    said: str = Field(description="the requester's words")


class Evidence(BaseModel):
    """Which words gave which part of the reading."""

    model_config = ConfigDict(frozen=True)

    words: str
    meaning: str


class TaskFrame(BaseModel):
    """What the requester wants, or the question to ask them first, or why nothing is done."""

    requester: str
    tasks: list[Task] = Field(default_factory=list)
    question: str | None = Field(default=None, description="set when the request is unclear")
    decline: str | None = Field(
        default=None, description="set when nothing is to be done: the message that says why"
    )
    decline_outcome: DeclineOutcome = "unachievable"
    hints: list[Hint] = Field(default_factory=list)
    evidence: list[Evidence] = Field(default_factory=list)

    @property
    def understood(self) -> bool:
        return self.question is None and self.decline is None and bool(self.tasks)

    def away(self) -> set[str]:
        """People the requester said are away."""
        return {h.person for h in self.hints if h.kind == "availability" and h.value == "away"}

    def unusable(self, item_type: str) -> set[str]:
        """Owners whose ``item_type`` the requester said is broken, lost or missing."""
        return {h.person for h in self.hints if h.kind == "condition" and h.item_type == item_type}

    def explain(self) -> str:
        """The reading in words: what each phrase was taken to mean."""
        return "; ".join(f"{e.words!r} → {e.meaning}" for e in self.evidence)


_KIND_SHAPE = {kind: shape for shape, kind in SHAPE_KIND.items()}


def operation_of(office: Office, task: Task) -> str | None:
    """The office operation a task needs: the one the frame names, the one that makes its
    product, or the office's one operation of the task's shape; None for person-to-person
    tasks (transfer, sign, seal, send_file)."""
    if task.operation is not None:
        return task.operation
    if task.kind == "produce":
        made = office.making(task.item or "")
        return made.id if made else None
    shape = _KIND_SHAPE.get(task.kind)
    if shape is None:
        return None
    found = office.with_shape(shape)
    return found[0].id if found else None
