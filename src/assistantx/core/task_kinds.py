"""The one table of task kinds: what each kind of task is, who does it and how it is said.

Every part of the assistant that treats task kinds differently reads this table instead of a
``match`` of its own: the task schema (milestones, the dataset's part kinds, the operation
shape a kind runs), the lock (the purpose of a work code and whether the item comes back),
the planner (the hand-over steps and the doer's role), the simulated people (what a work code
leaves true in the world) and the words told to people (the step at the locker, the task in a
plan, the outcome).

A kind is one :class:`KindSpec`. The office-facing kinds (``shape`` set) take their *verbs*
from the office's own operation ("scan", "shred", "fax"), so a new service of an existing
shape is an office-file entry alone; the text templates here only fill in the operation's own
words. The fields:

- ``shape``: the shape of office operation the kind runs (``office.Operation.shape``), None
  for a person-to-person kind (a signature) or a plain move of an item;
- ``parts``: the part kinds of the dataset's base instructions that ask for it;
- ``milestone``: the world-state predicate a finished task of this kind makes true;
- ``purpose``: the lock code's purpose of its work step (None: no work step at the locker);
- ``doer``: the role that does the work ("signer", "heater"), for the plan's role keys;
- ``steps``: the hand-over steps of the plain case, in order: who meets the robot
  (``source``, ``doer``, ``recipient``) and the code's purpose there;
- ``locker``: what the doer does at the locker when the office has no operation to name it
  ({item}: the item's phrase);
- ``todo``: the task in a plan's words ({verb} the operation's name, {whose} the item's
  phrase, {to} the recipient, {by} the actor, {owner_s} "your"/"Lee Ming's", {file} what
  the office calls a person's file: ``wording.file_noun``); ``todo_sent`` when its operation
  sends the item outside ({dest}: where, in the requester's words): "courier your drawings
  to Harlow";
- ``done``: the outcome told to the requester ({done}: the operation's past participle;
  {was}: "was", or "were" after a plural item, "your clippers were sharpened");
- ``works_on``: the property of the item type a person-to-person kind works on ("signable":
  the office's paper), never a type id;
- ``tool``: the property of the item type its doer must own ("seals": whoever owns the
  office's seal can stamp), None when anyone named may do it;
- ``ask``: what the doer of a person-to-person kind is asked to do ({whose}: the item's phrase,
  {your}: "your" to one person, "a" to a group);
- ``words``: the English words that ask for a person-to-person kind, for the simulated
  people's reading (the built-in kinds keep theirs in ``data/english.yaml``);
- ``which_item``: the words after "Which item do you mean" when a request names no item ("for
  me to bring"; a kind run by an office's service is asked about in the service's names).

The table is the one source of the kinds: the schema's ``TaskKind``, the dataset's part kinds
and the lock's code purposes are checked against it when a task, a part or a code is built,
so a new kind is one :func:`add` of a :class:`KindSpec` (a person-to-person kind, the shape of
sign and seal) and no other code. A kind of an office operation's shape is not added this way:
the shapes are the office's (``office.OperationShape``) and each has its kind already.

This module sits in the domain core with the office and imports nothing above it.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

from assistantx.core.office import ItemProperty, Office, OperationShape

Party = Literal["source", "doer", "recipient"]


@dataclass(frozen=True)
class Step:
    """One hand-over at the locker: who meets the robot and what their code is for."""

    party: Party
    purpose: str


@dataclass(frozen=True)
class KindSpec:
    """One kind of task (see the module docstring for each field)."""

    id: str
    parts: tuple[str, ...]
    milestone: str
    todo: str
    done: str
    shape: OperationShape | None = None
    by_person: bool = False
    purpose: str | None = None
    doer: str | None = None
    steps: tuple[Step, ...] = ()
    locker: str | None = None
    returns: bool = True
    done_consumed: str | None = None  # the outcome when the operation consumes the item
    done_sent: str | None = None  # the outcome when it sent the item outside ({dest}: where)
    todo_sent: str | None = None  # the task in a plan's words when it sends the item outside
    done_file: str | None = None  # the outcome when its product is a file sent by message
    # the outcome when the product went to someone else and the original back to the requester
    done_elsewhere: str | None = None
    works_on: ItemProperty | None = None
    tool: ItemProperty | None = None
    ask: str | None = None
    words: tuple[str, ...] = ()
    # "Which item do you mean <which_item>?" when a request names none ("for me to bring");
    # a kind run by an office's service is asked about in the service's own names instead
    which_item: str = ""

    @property
    def works_at_locker(self) -> bool:
        """Whether a person takes the item out of the locker, works on it and puts it back
        (or, for a kind that does not return it, keeps it)."""
        return self.purpose is not None and self.purpose != "produce"


# The work-on-the-item pattern: the item goes in, the doer works on it, the recipient collects.
_WORK = (Step("source", "deposit"), Step("doer", "{purpose}"), Step("recipient", "collect"))


def _work(purpose: str) -> tuple[Step, ...]:
    return tuple(Step(s.party, s.purpose.format(purpose=purpose)) for s in _WORK)


_BUILT_IN: tuple[KindSpec, ...] = (
    KindSpec(
        id="transfer",
        which_item="for me to bring",
        parts=("fetch", "deliver"),
        milestone="holds",
        steps=(Step("source", "deposit"), Step("recipient", "collect")),
        todo="bring {whose} to {to}",
        done="{to} now {have} {whose}",
    ),
    KindSpec(
        id="print",
        parts=("print",),
        milestone="printed",
        shape="render",
        purpose="produce",
        doer="renderer",
        todo="{verb} {owner_s} {file} for {to}",
        done="the {product} of {owner_s} {file} was handed to {to}",
    ),
    KindSpec(
        id="copy",
        parts=("copy",),
        milestone="copied",
        shape="transform",
        purpose="copy",
        doer="copier",
        locker="take {item} out, copy it and put the original and the copy back",
        todo="{verb} {whose} for {to}",
        done="{whose} and its {product} were handed to {to}",
        done_elsewhere=(
            "the {product} of {whose} was handed to {to}, and the original back to {back}"
        ),
        done_file="{whose} {was} {done}: the {product} was sent to {to} by message",
    ),
    KindSpec(
        id="sign",
        which_item="to be signed",
        parts=("sign",),
        milestone="signed",
        by_person=True,
        works_on="signable",
        ask="sign {whose}",
        purpose="sign",
        doer="signer",
        steps=_work("sign"),
        locker="take {item} out, sign it and put it back",
        todo="get {whose} signed by {by}",
        done="{whose} {was} signed by {by} and handed to {to}",
    ),
    KindSpec(
        id="seal",
        which_item="to be stamped",
        parts=("seal",),
        milestone="sealed",
        by_person=True,
        works_on="signable",
        tool="seals",
        ask="stamp {whose} with {your} seal",
        purpose="seal",
        doer="sealer",
        steps=_work("seal"),
        locker="take {item} out, stamp it with the seal and put it back",
        todo="get {whose} stamped with the seal",
        done="{whose} {was} stamped with the seal and handed to {to}",
    ),
    KindSpec(
        id="produce",
        parts=("make",),
        milestone="made",
        shape="make",
        purpose="produce",
        doer="maker",
        steps=(Step("doer", "produce"), Step("recipient", "collect")),
        locker="make {item} and put it into the locker",
        todo="get {item} for {to}",
        done="{item} {was} handed to {to}",
    ),
    KindSpec(
        id="heat",
        parts=("heat",),
        milestone="heated",
        shape="treat",
        purpose="heat",
        doer="heater",
        steps=_work("heat"),
        locker="take {item} out, heat it and put it back",
        todo="{verb} {whose} for {to}",
        done="{whose} {was} {done} and handed to {to}",
        done_consumed="{whose} {was} {done}",
        done_sent="{whose} {was} {done} to {dest}",
        todo_sent="{verb} {whose} to {dest}",
    ),
    KindSpec(
        id="send_file",
        which_item="for me to pass on",
        parts=("forward_file", "get_file"),
        milestone="received",
        works_on="electronic",
        todo="pass {owner_s} {file} to {to}",
        done="{owner_s} {file} was passed to {to}",
    ),
)

_BY_ID: dict[str, KindSpec] = {k.id: k for k in _BUILT_IN}
# The code purposes that are no kind's work step: the item goes in, the item comes out.
MOVE_PURPOSES: tuple[str, ...] = ("deposit", "collect")


def kinds() -> tuple[KindSpec, ...]:
    """Every kind of the table, the built-in ones first, in the order they were added."""
    return tuple(_BY_ID.values())


def add(spec: KindSpec) -> None:
    """Add a kind to the table; ValueError says why an entry does not fit beside the others."""
    taken = [
        f"the id {spec.id!r}" if spec.id in _BY_ID else "",
        *(f"the part kind {p!r}" for p in spec.parts if of_part(p) is not None),
        f"the milestone {spec.milestone!r}" if of_milestone(spec.milestone) else "",
        f"the purpose {spec.purpose!r}"
        if spec.purpose in (*MOVE_PURPOSES, *(k.purpose for k in kinds()))
        else "",
    ]
    problems = [f"{t} is taken" for t in taken if t]
    if spec.shape is not None:
        problems.append(f"the shape {spec.shape!r} is the office's, with its kind already")
    if spec.by_person and spec.purpose != spec.id:
        problems.append("a person-to-person kind's purpose is its id (the doer's code)")
    if problems:
        raise ValueError(f"task kind {spec.id!r} does not fit the table: {'; '.join(problems)}")
    _BY_ID[spec.id] = spec


def remove(kind_id: str) -> None:
    """Take an added kind out of the table again (a test's kind); the built-in ones stay."""
    if any(k.id == kind_id for k in _BUILT_IN):
        raise ValueError(f"{kind_id!r} is a built-in task kind")
    _BY_ID.pop(kind_id, None)


def kind(kind_id: str) -> KindSpec:
    """The table's entry for a task kind; KeyError names the known kinds."""
    try:
        return _BY_ID[kind_id]
    except KeyError:
        raise KeyError(f"unknown task kind {kind_id!r}; known: {', '.join(_BY_ID)}") from None


def of_shape(shape: OperationShape) -> KindSpec | None:
    """The kind that runs an office operation of ``shape`` (None: a room to use)."""
    return next((k for k in kinds() if k.shape == shape), None)


def of_milestone(milestone: str) -> KindSpec | None:
    return next((k for k in kinds() if k.milestone == milestone), None)


def of_part(part: str) -> KindSpec | None:
    return next((k for k in kinds() if part in k.parts), None)


def of_purpose(purpose: str) -> KindSpec | None:
    """The kind whose work step a lock code of ``purpose`` is (None: deposit, collect)."""
    return next((k for k in kinds() if k.purpose == purpose and k.works_at_locker), None)


def part_kinds() -> tuple[str, ...]:
    """The part kinds of the dataset's base instructions, from every kind of the table."""
    return tuple(part for k in kinds() for part in k.parts)


def purposes() -> tuple[str, ...]:
    """Every purpose a lock code may have: the item in and out, and each kind's work step."""
    work = (k.purpose for k in kinds() if k.purpose is not None)
    return tuple(dict.fromkeys((*MOVE_PURPOSES, *work)))


def milestone_arity(milestone: str) -> int | None:
    """How many arguments an added person-to-person kind's milestone takes: the item and its
    doer when a named person does it, the item alone when whoever owns the tool may (None:
    not such a kind's milestone)."""
    spec = of_milestone(milestone)
    if spec is None or not spec.by_person:
        return None
    return 2 if spec.tool is None else 1


def known_kind(value: str) -> str:
    """A task kind of the table, as is; ValueError names the known ones (a pydantic check)."""
    if value not in _BY_ID:
        raise ValueError(f"unknown task kind {value!r}; known: {', '.join(_BY_ID)}")
    return value


def known_purpose(value: str) -> str:
    """A lock code purpose of the table, as is; ValueError names the known ones."""
    if value not in purposes():
        raise ValueError(f"unknown code purpose {value!r}; known: {', '.join(purposes())}")
    return value


def works_on_item(kind_id: str) -> bool:
    """Whether a kind is the plain work-on-the-item pattern: the item goes into the locker,
    its doer works on it, its recipient takes it out (sign, seal, heat)."""
    spec = kind(kind_id)
    return spec.purpose is not None and spec.steps == _work(spec.purpose)


def work_purposes() -> frozenset[str]:
    """The code purposes for which a person takes the item out of the locker and works on it."""
    return frozenset(k.purpose for k in kinds() if k.purpose and k.works_at_locker)


def person_kinds() -> tuple[str, ...]:
    """The kinds a person does for the requester with no facility (their words are English)."""
    return tuple(k.id for k in kinds() if k.by_person)


def tool_type(kind_id: str, office: Office) -> str | None:
    """The item type the doer of a kind must own (the office's seal for ``seal``); None when
    the kind needs no tool or is unknown."""
    spec = _BY_ID.get(kind_id)
    return office.type_with(spec.tool) if spec is not None and spec.tool else None


def needs_tool(kind_id: str) -> bool:
    spec = _BY_ID.get(kind_id)
    return spec is not None and spec.tool is not None


def item_type_of(kind_id: str, office: Office) -> str | None:
    """The item type a person-to-person kind works on, by its property (the signable paper)."""
    spec = kind(kind_id)
    return office.type_with(spec.works_on) if spec.works_on else None


def kind_of(kind_id: str) -> bool:
    """Whether ``kind_id`` is a task kind of the table (role kinds like "lend" are not)."""
    return kind_id in _BY_ID
