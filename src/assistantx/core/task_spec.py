"""Base instructions: free text plus a structured spec of what the text means.

``dataset/base_instructions.yaml`` lists them; each names its requester, the instruction text
and its ``parts`` (one ``task_schema.Part`` per task; several parts make a combination). The
goal milestones, the roles to fill and the optimal plan are all computed from the parts, never typed
by hand. A part's fields:

- ``kind``: ``fetch`` (``item``; ``owner`` for a named owner, else anyone's will do),
  ``deliver`` (the requester's ``item`` ``to`` someone), ``print`` (the requester's file,
  printed and brought ``to`` someone, default the requester), ``copy`` (the requester's
  document), ``sign`` (the requester's document, by ``signer``), ``seal`` (the requester's
  document, stamped by any seal owner), ``coffee`` / ``water`` / ``snack`` (made at the facility
  and brought to the requester), ``heat`` (the requester's lunch, from the fridge to the
  microwave), ``forward_file`` (the requester's file ``to`` someone), ``get_file`` (the
  ``owner``'s file, forwarded to the requester).
"""

from __future__ import annotations

from pathlib import Path

from pydantic import BaseModel, ConfigDict, Field, ValidationError

from assistantx.core import task_kinds
from assistantx.core.errors import DatasetError
from assistantx.core.office import Office, Operation
from assistantx.core.task_schema import PART_NEEDS, Part, Task
from assistantx.core.yaml_file import read_yaml

__all__ = ["BaseInstruction", "Part", "load_base_instructions", "part_operation"]


class BaseInstruction(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)

    id: str = Field(min_length=1)
    requester: str
    text: str = Field(min_length=1)
    parts: tuple[Part, ...] = Field(min_length=1)

    @property
    def kinds(self) -> list[str]:
        return [p.kind for p in self.parts]

    def tasks(self, office: Office) -> list[Task]:
        """The parts as the task schema reads them: what the instruction's text must mean."""
        return [p.task(self.requester, office) for p in self.parts]


def load_base_instructions(path: str | Path, office: Office) -> list[BaseInstruction]:
    """Load and check base instructions against the office; problems raise DatasetError."""
    file = Path(path)
    raw = read_yaml(file, lambda why: DatasetError(f"{file}: {why}"))
    entries = raw.get("instructions") if isinstance(raw, dict) else None
    if not isinstance(entries, list):
        raise DatasetError(f"{file}: expected a mapping with a list under 'instructions'")
    bases: list[BaseInstruction] = []
    for n, entry in enumerate(entries):
        try:
            base = BaseInstruction.model_validate(entry)
        except ValidationError as exc:
            err = exc.errors()[0]
            where = ".".join(str(p) for p in err["loc"])
            raise DatasetError(f"{file}: instructions[{n}].{where}: {err['msg']}") from exc
        for k, part in enumerate(base.parts):
            if part.kind not in task_kinds.part_kinds() and not made_kind(office, part.kind):
                raise DatasetError(
                    f"{file}: instructions[{n}].parts[{k}].kind: unknown kind {part.kind!r}: "
                    f"one of {', '.join(task_kinds.part_kinds())}, or a product an operation of "
                    "the office makes"
                )
        try:
            check_base(base, office)
        except (KeyError, ValueError) as exc:
            raise DatasetError(f"{file}: instruction {base.id}: {exc}") from exc
        bases.append(base)
    ids = [b.id for b in bases]
    if len(set(ids)) != len(ids):
        raise DatasetError(f"{file}: duplicate instruction ids")
    return bases


def _owns(office: Office, person: str, item_type: str) -> bool:
    return any(o.type == item_type for o in office.person(person).owns)


def made_kind(office: Office, kind: str) -> bool:
    """Whether a part kind names a product of the office ("coffee": make a coffee)."""
    return kind not in task_kinds.part_kinds() and office.making(kind) is not None


def part_operation(office: Office, part: Part) -> Operation:
    """The office operation an operating part needs (raises ValueError when there is none)."""
    shape = part.shape(office)
    if shape is None:
        raise ValueError(f"{part.kind} uses no facility")
    if part.operation is not None:
        op = office.operation(part.operation)
    elif shape == "make":
        product = part.item if part.kind == "make" else part.kind
        found = office.making(product or "")
        if found is None:
            raise ValueError(f"no operation makes {product!r}")
        op = found
    else:
        ops = office.with_shape(shape)
        if not ops:
            raise ValueError(f"the office has no operation for {part.kind}")
        op = ops[0]
        if len(ops) > 1:
            # a photocopier and a scan to PDF both copy: the one the kind names, never
            # whichever the office file happens to list first
            named = [o for o in ops if part.kind == o.id or part.kind in o.verbs]
            if len(named) != 1:
                raise ValueError(
                    f"several operations do {part.kind} here ({', '.join(o.id for o in ops)}):"
                    " name one with operation:"
                )
            op = named[0]
    if op.shape(office) != shape:
        raise ValueError(f"operation {op.id!r} does not fit {part.kind}")
    if not office.offering(op.id):
        raise ValueError(f"no facility does {op.id!r}")
    return op


def _own_kept(office: Office, part: Part, requester: str) -> bool:
    """Whether ``part`` fetches the requester's own item from where it is kept (their lunch
    from the fridge): the keeper hands it out, so the requester may name themselves."""
    if part.kind != "fetch" or part.owner != requester or part.item is None:
        return False
    return _owns(office, requester, part.item) and office.keeper(requester, part.item) is not None


def check_base(base: BaseInstruction, office: Office) -> None:
    """The spec must make sense in the office (raises KeyError/ValueError saying why)."""
    a = base.requester
    office.person(a)
    for part in base.parts:
        if part.kind not in task_kinds.part_kinds() and not made_kind(office, part.kind):
            raise ValueError(
                f"unknown kind {part.kind!r}: one of {', '.join(task_kinds.part_kinds())}, or a "
                "product an operation of the office makes"
            )
        for person in (part.owner, part.to, part.signer):
            if person is not None:
                office.person(person)
                if person == a and not _own_kept(office, part, a):
                    raise ValueError(f"{part.kind}: the requester cannot be the other party")
        if part.item is not None:
            office.item_type(part.item)
        for field in PART_NEEDS.get(part.kind, ()):
            if getattr(part, field) is None:
                raise ValueError(f"{part.kind} needs {field!r}")
        if part.kind == "fetch":
            assert part.item is not None
            if part.to is not None:
                # a fetch brings the thing to the requester; read silently, "to" was dropped
                # and the goal had the requester holding it
                raise ValueError(
                    "fetch brings the item to the requester; 'to' is not read (a thing "
                    "fetched for someone else is not a fetch part)"
                )
            if office.item_type(part.item).kind not in ("belonging", "personal"):
                raise ValueError("fetch is for physical items")
            # "mine is leaking": asking for one of a kind you own is asking for someone else's
            if part.owner is not None and not _owns(office, part.owner, part.item):
                raise ValueError(f"{part.owner} owns no {part.item}")
            supplied = office.supplier(part.item) is not None  # a shared one, nobody's
            if part.owner is None and not supplied and not set(office.owners_of(part.item)) - {a}:
                raise ValueError(f"nobody but the requester owns a {part.item}")
        if part.kind == "deliver":
            assert part.item is not None
            if not _owns(office, a, part.item):
                raise ValueError(f"the requester owns no {part.item}")
        kind = part.task_kind()
        file = task_kinds.item_type_of("send_file", office)
        if kind in task_kinds.person_kinds():  # a person's work on the kind's paper (+ its tool)
            paper = task_kinds.item_type_of(kind, office)
            if paper is None or not _owns(office, a, paper):
                raise ValueError(f"the requester has nothing to {kind}")
            tool = task_kinds.tool_type(kind, office)
            if task_kinds.needs_tool(kind) and (tool is None or _owns(office, a, tool)):
                raise ValueError(f"the requester owns a {tool} already, or the office has none")
        if part.kind == "forward_file" and (file is None or not _owns(office, a, file)):
            raise ValueError("the requester has no file")
        if part.kind == "get_file":
            assert part.owner is not None
            if file is None or not _owns(office, part.owner, file):
                raise ValueError(f"{part.owner} has no file")
        if part.shape(office) is not None:
            op = part_operation(office, part)
            if op.input is not None and not _owns(office, a, op.input):
                raise ValueError(f"the requester has no {op.input}")
            facility = office.offering(op.id)[0]
            if not facility.guards:
                raise ValueError(f"nobody runs the {facility.id}")
            if op.sends_out and part.destination is None:
                # whatever goes out unaddressed is lost: an instruction that does not say where
                # is met with a question, and its answer is part of the task's spec
                raise ValueError(
                    f"{op.id} sends the item out of the office: the part needs its destination "
                    f"({op.destination_asked})"
                )
            # a guard may ask too: another guard runs it, or, when the requester is the only
            # one, they run it themselves with the robot (agents/oracle/policy.runs_it_alone)
