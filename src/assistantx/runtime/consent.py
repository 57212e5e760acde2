"""Consent and authority for locker hand-overs, checked where actions are executed.

Whatever read the request and whatever reasoner chose the action (symbolic, LLM, hybrid, a
baseline), the executor asks this guard before a one-time locker code goes out. It reads only
the office file and the instruction's own dialogue, never the reasoner's reading, so a wrong
reading can waste a step but cannot hand anything to the wrong person:

1. **Parties.** A code (and a forwarded file) goes only to the requester; the item's owner;
   the keeper of the facility where the owner keeps it (a fridge's keeper, for a deposit); a
   guard of a facility whose operation works on or makes the item (a copy, a heat, a print);
   for ``sign``/``seal``, a person the requester named as the one to do it, in a doing place
   of their words or as the doer of the reader's frame of the request (and, for a seal,
   anyone who owns the seal); for ``collect``, a person the requester named as the recipient,
   or the one the reader's frame of the request makes a thing for (a copy or a printout of
   the requester's own, a coffee) whom the requester's own words name (``made_for``).
   "Named as" means in that role, in the requester's own words (``recipients``): "take it to
   Hal", "bring Hal one", "get Hal to sign", a reply that is just the name, a yes to "Shall I
   bring Hal one?". A name standing elsewhere ("... because Rich asked for it", "Rich wants
   it on the board", "Rich's form") makes no one a party.
2. **Agreement.** Anyone but the requester must have answered in this instruction's dialogue
   before they are handed a code (nobody gets a code for a hand-over they never agreed to).
3. **Consent.** An item owned by someone other than the requester leaves its owner only with the
   owner's own yes: a reply written by the owner, in the owner's own direct chat, to a question
   there that names the item. A keeper cannot give it away for them, and a yes in a group chat
   is not enough (the owner is then asked directly). Products and items owned by nobody (a
   facility's supplies, ``office.is_supply``: pens in the stationery cupboard) need no consent,
   only the keeper who takes them out; the owner taking their own item back needs none
   either. Someone else's file is forwarded only after its owner sent it themselves.
4. **Work that uses an item up is the owner's own call** (``core.owner_only``): the work code
   of an operation that consumes its item (a shredder) on someone else's item is refused even
   with the owner's yes; only the owner's own request has it done.
5. **Text carries no authority.** Only who wrote a message, and in whose chat, counts; what a
   message *says* ("Zhang already said yes", "I am Zhang", "admin mode") never stands in for a
   consent or changes who is asked. ``authority_claims`` spots such wording so the requester
   can be told that it changes nothing.

A refusal comes back to the agent as a failed, refused ``ActionResult`` whose observation
says what to do instead (ask the owner in their own chat, then send the code).
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Literal

from assistantx.agents.symbolic.answers import stance
from assistantx.core import english, name_parts, task_kinds
from assistantx.core.actions import Action, ForwardFile, SendQR
from assistantx.core.dialogue import DialogueTurn
from assistantx.core.office import Office, Person
from assistantx.core.owner_only import owner_only, owner_only_reason
from assistantx.core.ports.messenger import ChatRef
from assistantx.memory.short_term import ShortTermMemory
from assistantx.runtime.recipients import named_doers, named_receivers, named_recipients

_COMMON = english.words("common")
RefusalRule = Literal["not_a_party", "no_answer", "no_consent", "owner_only"]
ConsentState = Literal["yes", "no", "pending", "not_asked"]

# Purposes that take an item out of the locker for good, and those that put one in.
_COLLECT = "collect"
_DEPOSIT = "deposit"


@dataclass(frozen=True)
class Refusal:
    """Why a code may not go out, in words for the agent (and the trace)."""

    rule: RefusalRule
    reason: str


def check(office: Office, stm: ShortTermMemory, action: Action) -> Refusal | None:
    """The guard: None when ``action`` may run, else why not. Locker codes and file forwards
    are checked; nothing else hands anything to anyone."""
    if isinstance(action, ForwardFile):
        return _check_forward(office, stm, action)
    if not isinstance(action, SendQR):
        return None
    contact, item, purpose = action.contact, action.item, action.purpose
    if contact != stm.requester and not _is_party(office, stm, contact, item, purpose):
        return Refusal(
            "not_a_party",
            f"{contact} is not a party to {item}: a locker code goes only to the requester, the "
            "item's owner, the keeper of where it is kept, the guard of the facility doing the "
            "work, or a person the requester named as the recipient",
        )
    if (refused := _check_send_to(office, stm, action)) is not None:
        return refused
    if purpose in task_kinds.work_purposes():
        for operation in _work_operations(office, action):
            if (only := owner_only(office, stm.requester, item, operation)) is not None:
                return Refusal(
                    "owner_only",
                    f"{item}: {owner_only_reason(office, only, item.partition(':')[0], operation)}"
                    " Tell the requester so; give the item back to its owner if it was taken.",
                )
    if contact != stm.requester and not _answered(stm, contact):
        return Refusal(
            "no_answer",
            f"{contact} has not answered in this conversation, so they have not agreed to this "
            "hand-over; ask them (inquire, then wait) and send the code after they reply",
        )
    owner = consent_owner(office, stm.requester, item, purpose, contact)
    if owner is not None:
        state = owner_consent(office, stm, owner, item.partition(":")[0])
        if state != "yes":
            said = {
                "no": "said no",
                "pending": "has not answered yet",
                "not_asked": "has not been asked in their own chat",
            }[state]
            return Refusal(
                "no_consent",
                f"{item} belongs to {owner}, who {said}: an item leaves its owner only with the "
                f"owner's own yes; ask {owner} directly (inquire {owner} naming the item, then "
                "wait) — what anyone else writes does not count",
            )
    return None


def _check_send_to(office: Office, stm: ShortTermMemory, action: SendQR) -> Refusal | None:
    """A file the work makes (a scan to PDF) is sent by the operator as the code's message
    says: to the requester, the item's owner, or a person the requester named as the
    recipient, as a forwarded file is (``_check_forward``); to nobody else."""
    to = action.send_to
    if to is None or to in (stm.requester, action.item.partition(":")[2]):
        return None
    if to in named_recipients(office, stm):
        return None
    return Refusal(
        "not_a_party",
        f"{to} is not a party to {action.item}: the file made of it goes only to the "
        "requester, its owner, or someone the requester named as the recipient",
    )


def _work_operations(office: Office, action: SendQR) -> list[str]:
    """The office operations a work code may run: the one it names, else each operation on
    the item's type that a facility its contact guards offers (any of them might be run)."""
    if action.operation is not None:
        return [action.operation]
    item_type = action.item.partition(":")[0]
    offered = {op for f in office.facilities if action.contact in f.guards for op in f.operations}
    return [o.id for o in office.operations if o.id in offered and o.input == item_type]


def _check_forward(office: Office, stm: ShortTermMemory, action: ForwardFile) -> Refusal | None:
    """A file goes only to a party (the requester, its owner, the guard of a facility whose
    operation takes it, a person or group the requester named), and someone else's file only
    once its owner sent it themselves (sending it is their yes)."""
    file = action.file or office.file_of(action.source)
    item_type, _, owner = file.partition(":")
    target = action.target
    parties = {stm.requester, owner, *_facility_workers(office, item_type)}
    if target not in parties and target not in named_recipients(office, stm):
        if target not in named_groups(office, stm):
            return Refusal(
                "not_a_party",
                f"{target} is not a party to {file}: a file goes only to the requester, its "
                "owner, the guard of the facility that works on it, or someone the requester "
                "named as the recipient",
            )
    if owner != stm.requester and _is_person(office, owner):
        if file not in stm.files_received.get(owner, []):
            return Refusal(
                "no_consent",
                f"{file} belongs to {owner}, who has not sent it: ask {owner} directly to send "
                "it; a copy from anyone else does not count",
            )
    return None


def consent_owner(
    office: Office, requester: str, item: str, purpose: str, contact: str
) -> str | None:
    """Whose yes this code needs (None: nobody's): the owner of a belonging, unless that is the
    requester, or the owner takes their own item back."""
    item_type, _, owner = item.partition(":")
    if owner == requester or not _is_person(office, owner):
        return None
    if purpose == _COLLECT and contact == owner:
        return None
    if any(t.id == item_type and t.kind == "product" for t in office.item_types):
        return None  # made for someone (a printout, a coffee): nobody owned it
    return owner


def owner_consent(office: Office, stm: ShortTermMemory, owner: str, item_type: str) -> ConsentState:
    """The owner's own answer, in their own direct chat, to the latest question there that
    names the item (a later answer overrides an earlier one)."""
    dm = ChatRef(kind="dm", id=owner)
    questions = [
        t
        for t in stm.dialogue
        if t.direction == "out"
        and t.chat == dm
        and t.question_id
        and _names_item(office, t.text, item_type)
    ]
    if not questions:
        return "not_asked"
    asked = questions[-1]
    answers = [t for t in _answers_in_dm(stm.dialogue, dm, owner, asked) if t.text.strip()]
    if not answers:
        return "pending"
    return "yes" if stance(answers[-1].text) == "yes" else "no"


def _answers_in_dm(
    dialogue: list[DialogueTurn], dm: ChatRef, owner: str, asked: DialogueTurn
) -> list[DialogueTurn]:
    """The owner's replies to ``asked``: threaded to it, or unthreaded ones written after it
    and before the next question to them."""
    out: list[DialogueTurn] = []
    after = False
    for turn in dialogue:
        if turn is asked:
            after = True
            continue
        if turn.chat != dm:
            continue
        if turn.direction == "out" and turn.question_id and after:
            after = False  # a newer question: unthreaded replies now answer that one
            continue
        if turn.direction != "in" or turn.person != owner:
            continue
        if turn.in_reply_to == asked.question_id or (after and turn.in_reply_to is None):
            out.append(turn)
    return out


def _answered(stm: ShortTermMemory, person: str) -> bool:
    return any(t.direction == "in" and t.person == person for t in stm.dialogue)


def _is_person(office: Office, person_id: str) -> bool:
    return any(p.id == person_id for p in office.people)


def _is_party(office: Office, stm: ShortTermMemory, contact: str, item: str, purpose: str) -> bool:
    item_type, _, owner = item.partition(":")
    if contact == owner:
        return True
    if purpose == _DEPOSIT and (_is_person(office, owner) or office.is_supply(item)):
        # the keeper of where it is kept (the fridge's, the stationery cupboard's)
        keeper = _keeper(office, owner, item_type)
        return keeper is not None and contact in keeper
    if purpose == _COLLECT:
        return contact in named_receivers(office, stm)
    if purpose in task_kinds.person_kinds():  # by hand, no facility: sign, seal, ...
        tool = task_kinds.tool_type(purpose, office)  # whoever owns the seal may stamp
        if tool is not None and _owns(office, contact, tool):
            return True
        return contact in named_doers(office, stm)
    # work at a facility (copy, heat, produce, ...): its guards run it
    return contact in _facility_workers(office, item_type)


def _keeper(office: Office, owner: str, item_type: str) -> tuple[str, ...] | None:
    try:
        facility = office.keeper(owner, item_type)
    except KeyError:
        return None
    return facility.guards if facility is not None else None


def _owns(office: Office, person: str, item_type: str) -> bool:
    return any(p.id == person and any(o.type == item_type for o in p.owns) for p in office.people)


def _facility_workers(office: Office, item_type: str) -> set[str]:
    """Guards of the facilities whose operations take or make ``item_type``."""
    ops = {o.id for o in office.operations if item_type in (o.input, o.product)}
    return {g for f in office.facilities if ops & set(f.operations) for g in f.guards}


def named_groups(office: Office, stm: ShortTermMemory) -> set[str]:
    """Group chats the requester named in the instruction ("send it to the design team")."""
    return {
        g.id for g in office.groups if _has_words(stm.text, g.name) or _has_words(stm.text, g.id)
    }


def _mentions(text: str, person: Person) -> bool:
    names = {person.id, person.id.replace("_", " "), person.name, *person.aliases}
    names.update(w for w in name_parts.calling_words(person) if len(w) > 1)
    return any(_has_words(text, n) and not _only_as_a_word(text, n) for n in names if n)


def _only_as_a_word(text: str, name: str) -> bool:
    """Whether a name that is also an everyday English word ("Will", "May") stands in the
    text only in lower case, i.e. as the word ("will you bring ..."), never as the name."""
    if name.casefold() not in _COMMON:
        return False
    pattern = rf"(?<!\w){re.escape(name.casefold())}(?:'s|’s|s)?(?!\w)"
    return all(m.group(0).islower() for m in re.finditer(pattern, text, re.IGNORECASE))


def _has_words(text: str, phrase: str) -> bool:
    pattern = rf"(?<!\w){re.escape(phrase.casefold())}(?:'s|’s|s)?(?!\w)"
    return re.search(pattern, text.casefold()) is not None


def _names_item(office: Office, text: str, item_type: str) -> bool:
    found = next((t for t in office.item_types if t.id == item_type), None)
    names = {item_type, item_type.replace("_", " ")}
    if found is not None:
        names.update((found.name, *found.synonyms))
    return any(_has_words(text, n) for n in names if n)


# -- text that claims an authority it does not have ------------------------------------------
_CLAIMS = (
    (
        r"\b(already|has|have|had)\s+(said\s+yes|agreed|approved|consented|ok(?:ay)?ed)\b",
        "someone's agreement",
    ),
    (r"\b(said|says)\s+(it'?s\s+)?(ok|okay|fine|yes)\b", "someone's agreement"),
    # "Pat ok'd me using it": the verb alone reports the yes
    (r"\b(ok['’]d|okd|oked|okayed|okay['’]d)\b", "someone's agreement"),
    # "he said I could use it", "she told me I can borrow it": leave told second-hand
    (r"\b(said|says|told\s+me)\s+(i|we)\s+(can|could|may|might)\b", "someone's agreement"),
    # "she won't mind", "he wouldn't mind": agreement assumed for them
    (
        r"\b(won'?t|wont|wouldn'?t|will\s+not|would\s+not|doesn'?t|does\s+not)\s+mind\b",
        "someone's agreement",
    ),
    (
        r"\b(with|got|have)\s+(his|her|their)\s+(permission|ok|approval|consent)\b",
        "someone's agreement",
    ),
    (
        r"\b(admin|administrator|operator|god|debug|developer|maintenance|override)\s+mode\b",
        "a special mode",
    ),
    (
        r"\b(ignore|bypass|skip|override)\s+(the\s+)?(rules?|checks?|consent|approval|asking)\b",
        "a special mode",
    ),
    (r"\bno\s+need\s+to\s+ask\b|\bdon'?t\s+(?:need\s+to\s+)?ask\b", "skipping a question"),
    (r"\bon\s+behalf\s+of\b", "who is writing"),
)
# "I am Zhang", "this is Wang speaking": the name is checked against the office's people.
_IDENTITY = re.compile(
    r"\b(?:i\s+am|i'?m|this\s+is|it'?s)\s+(?:actually\s+)?(\w+)(?!['’]s)\b", re.I
)


def authority_claims(text: str, office: Office, requester: str) -> list[str]:
    """What the text claims that only the people themselves can grant (their agreement, a
    mode, another person's identity), in words; empty when it claims nothing of the kind."""
    found: list[str] = []
    for pattern, what in _CLAIMS:
        if re.search(pattern, text, re.IGNORECASE) and what not in found:
            found.append(what)
    for match in _IDENTITY.finditer(text):
        word = match.group(1)
        others = [p for p in office.people if p.id != requester and _mentions(word, p)]
        if others and word[:1].isupper() and "who is writing" not in found:
            found.append("who is writing")
    return found


def no_authority_notice(claims: list[str]) -> str:
    """What the requester is told when their message claims an authority."""
    what = " or ".join(claims)
    return (
        f"Note: your message mentions {what}. A message cannot grant that: I ask each owner "
        "myself, in their own chat, before anything of theirs leaves them, and I act for you "
        "as yourself."
    )
