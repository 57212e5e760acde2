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

from typing import Annotated, Literal

from pydantic import AfterValidator, BaseModel, ConfigDict, Field

from assistantx.core import task_kinds
from assistantx.core.office import Office, OperationShape

# The kinds of a task: one entry each in the table of ``task_kinds`` (its shape, milestone,
# hand-over steps and words). A string the table checks wherever a Task is built, so a kind
# added to the table is a kind here with no other change.
TaskKind = Annotated[str, AfterValidator(task_kinds.known_kind)]
# The task kind each shape of office operation takes (office.Operation.shape). The shapes are
# the office's and each has its kind in the built-in table, so this does not grow.
SHAPE_KIND: dict[OperationShape, TaskKind] = {
    k.shape: k.id for k in task_kinds.kinds() if k.shape is not None
}
FILE_KIND: TaskKind = "send_file"
# The coarse kinds of the usage report: what the robot did for an instruction. "none": it
# reached nobody but its requester (text not understood, a decline, a question back).
RecordKind = Literal["delivery", "file", "message", "none"]
RECORD_KINDS: tuple[RecordKind, ...] = ("delivery", "file", "message", "none")
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
    source: str | None = Field(
        default=None,
        description="where the item comes from when the frame fixes it: a person, or a "
        "facility or cupboard that keeps it",
    )
    facility: str | None = Field(
        default=None, description="the facility the requester named for the operation"
    )
    input_item: str | None = Field(
        default=None,
        description="the item type the operation works on (the requester's file, document, "
        "lunch); None when it makes something from nothing",
    )
    destination: str | None = Field(
        default=None,
        description="where an operation that sends the item outside sends it, in the "
        "requester's words ('the county tax office', '+44 20 7946 0000')",
    )

    def item_id(self) -> str | None:
        """The concrete item, when the frame fixes it (``stapler:zhang``, ``coffee:lee``)."""
        if self.item is None:
            return None
        if self.kind == "produce":
            return f"{self.item}:{self.recipient}"
        if self.kind == "print":
            return f"{self.input_item or self.item}:{self.owner}"
        return f"{self.item}:{self.owner}" if self.owner else None


class Hint(BaseModel):
    """A fact the requester stated, for memory: never a request, never a party to one."""

    model_config = ConfigDict(frozen=True)

    kind: HintKind
    person: str
    value: str = Field(description="'away'/'here', a location id, or a condition word")
    item_type: str | None = Field(default=None, description="the item a condition is about")
    said: str = Field(description="the requester's words")


# How the reader's evidence opens for a fallback it kept back ("bring me a stapler, or if
# there isn't one, scissors": only the stapler is fetched), so the outcome can say it was not
# used (reading/fallback.py, decision.py).
FALLBACK_MEANING = "a fallback: "


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


_KIND_SHAPE: dict[str, OperationShape] = {kind: shape for shape, kind in SHAPE_KIND.items()}


def kind_shape(kind: str) -> OperationShape | None:
    """The shape of office operation a task kind uses; None for person-to-person kinds."""
    return _KIND_SHAPE.get(kind)


# The written form of a task in the dataset's base instructions (``parts:`` of
# dataset/base_instructions.yaml): one part per task, kinds named from the requester's side
# (``task_kinds.part_kinds()``: every kind's ``parts``). Any other part kind must be a product
# of one of the office's operations ("make one").

# The fields each part kind must name (dataset.spec checks them).
PART_NEEDS: dict[str, tuple[str, ...]] = {
    "fetch": ("item",),
    "deliver": ("item", "to"),
    "forward_file": ("to",),
    "get_file": ("owner",),
    "sign": ("signer",),
}


class Part(BaseModel):
    """One task of a base instruction, as the dataset writes it; ``task`` reads it as a Task."""

    model_config = ConfigDict(extra="forbid", frozen=True)

    kind: str = Field(
        min_length=1, description="a part kind of the task_kinds table, or a product of the office"
    )
    item: str | None = Field(default=None, description="item type (fetch, deliver)")
    owner: str | None = Field(default=None, description="named owner (fetch, get_file)")
    to: str | None = Field(
        default=None, description="recipient (deliver, forward_file; print, copy, make, heat)"
    )
    signer: str | None = Field(default=None, description="who signs (sign)")
    operation: str | None = Field(
        default=None, description="the office operation, when several of the shape exist"
    )
    destination: str | None = Field(
        default=None, description="where an operation that sends outside sends it (fax)"
    )

    def task_kind(self) -> TaskKind:
        """The schema's kind of this part (a product's name is a ``produce``)."""
        spec = task_kinds.of_part(self.kind)
        return spec.id if spec is not None else "produce"

    def shape(self, office: Office) -> OperationShape | None:
        """The shape of office operation the part uses; None for person-to-person parts."""
        if self.kind not in task_kinds.part_kinds():
            return "make" if office.making(self.kind) is not None else None
        return kind_shape(self.task_kind())

    def task(self, requester: str, office: Office) -> Task:
        """This part as the task schema's :class:`Task` for ``requester``."""
        kind = self.task_kind()
        file = task_kinds.item_type_of("send_file", office)  # what is forwarded
        match self.kind:
            case "fetch":
                return Task(kind=kind, item=self.item, owner=self.owner, recipient=requester)
            case "deliver":
                return Task(kind=kind, item=self.item, owner=requester, recipient=self.to or "")
            case _ if task_kinds.kind(kind).by_person:  # sign, seal: on the kind's paper
                paper = task_kinds.item_type_of(kind, office)
                return Task(
                    kind=kind,
                    item=paper,
                    owner=requester,
                    recipient=requester,
                    actor=self.signer,
                    input_item=paper,
                )
            case "forward_file":
                return Task(kind=kind, item=file, owner=requester, recipient=self.to or "")
            case "get_file":
                return Task(kind=kind, item=file, owner=self.owner, recipient=requester)
        op = self.operation
        if kind == "produce":
            product = self.item if self.kind == "make" else self.kind
            made = office.making(product or "")
            return Task(
                kind=kind,
                item=product,
                recipient=self.to or requester,
                operation=op or (made.id if made else None),
            )
        found = office.with_shape(_KIND_SHAPE[kind]) if op is None else [office.operation(op)]
        operation = found[0] if found else None
        return Task(
            kind=kind,
            item=operation.input if operation else None,
            owner=requester,
            recipient=self.to or requester,
            operation=operation.id if operation else None,
            input_item=operation.input if operation else None,
            destination=self.destination,
        )


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
