"""The simulated requester: answers the assistant's questions from what they really want.

A person who asked for something knows what they meant. When the assistant asks them back,
they answer the question that was asked, from the task's truth (its goal milestones):

- a question that names options ("Do you mean Grace Obi, or the grace period talk?") gets the
  option that fits what they want ("the grace period talk");
- "Shall I ...?" gets "Yes, please." when the offer fits what they want, else "No, thanks."
  (the people an answer names before the offer, "As far as I know, Dov and Renée have a
  headset. Shall I bring you one?", are who has one, not whom it is for; a word the offer
  says that names a wanted item and another too, "your file" where the office also keeps a
  box file called a file, is the wanted one; an offer to do it "for you" is no to one who wants
  it for someone else);
- "Where should I courier it to?" gets the place outside the task sends it to ("To the
  regional federation.");
- "Who should get ...?" / "Whose ...?" (also both at once) / "Who should sign ...?" / "Who do
  you mean by 'his'?" get the person's name (or "Mine."), "Which item ...?" the item;
- "What should I do, with which item, and for whom?" (the whole request) and anything else get
  what they want, said plainly ("I mean Zhang Wei's stapler, for Min Ho.", "I mean the form:
  please courier it to the regional federation.");
- a question whose answer the truth does not hold gets "Sorry, I don't know." (never a guess).

The truth is the goal's milestones and, for an evaluation task, its parts (``Task.spec``): the
place outside a send-out service sends to and the service asked for are the requester's to
say, and no world-state milestone holds them.

A task that asks for nothing (its goal is only that the requester is told) answers every
offer with "No, thanks." The rules read only the question and the truth, never the
assistant's reading, so a wrong reading is corrected rather than confirmed.

Without a task (``assistantx run``: only the words they wrote are known, ``Wish.from_words``),
the requester still answers the question asked and nothing else: of two options, the one
whose words they wrote; to "where to?", the place after the "to" they wrote; to an offer,
"Yes, please." only when it is what their words ask for (the same people, items and work,
"your" for their "my": "Shall I get your condition report signed by Robin Okonkwo?" to
"robin okonkwo needs to sign my condition report"), else "No, thanks." (a yes would be a
guess at a wish nobody knows); to anything else, that they have nothing to add.
They never answer as a colleague would ("Yes, I have a stapler"), which read as a yes.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import dataclass, field

from assistantx.core import language, task_kinds
from assistantx.core.goals import Milestone, parse_milestone
from assistantx.core.name_reading import is_word_name
from assistantx.core.office import Office, Person
from assistantx.core.task_schema import Part
from assistantx.core.wording import verb_it
from assistantx.sim.able_doers import able_doers
from assistantx.sim.understanding import (
    mentioned_item_types,
    mentioned_requests,
    said_only_as_another,
)

_OFFER = re.compile(
    r"^\s*(?:ok(?:ay)?[,.]?\s+)?(shall|should|do you want me to|would you like me to|may|can|"
    r"want me to)\b",
    re.IGNORECASE,
)
_LEADS = re.compile(
    r"^(?:sorry[,.]?\s*)?(?:i still don'?t understand\.?\s*)?(?:do|did)\s+you\s+mean\s+|"
    r"^(?:which|who|what)\b[^:]*:\s*|^is\s+it\s+|^(?:either\s+)",
    re.IGNORECASE,
)


@dataclass(frozen=True)
class Wish:
    """What the requester wants, read from the task's goal."""

    requester: str
    recipients: tuple[str, ...] = ()
    owners: tuple[str, ...] = ()
    doers: tuple[str, ...] = ()  # signers, sealers
    items: tuple[str, ...] = ()  # item type ids, products and their inputs alike
    # whose the item is when it is not someone else's: "mine", "any" (any will do) or ""
    own: str = ""
    operations: tuple[str, ...] = ()  # the office operations asked for ("courier")
    destinations: tuple[str, ...] = ()  # where a send-out service sends it ("the federation")
    wants_something: bool = True
    people: frozenset[str] = field(default_factory=frozenset)
    # the words they wrote, when no task says what they want (``from_words``)
    words: str | None = None
    # whose each item of the goal is, where it is someone's (item type id, owner id)
    whose_items: tuple[tuple[str, str], ...] = ()
    # who could do wanted work whose milestone names no doer (``able_doers``): any of them
    # will do in place of a named colleague who is out
    able: frozenset[str] = frozenset()

    @classmethod
    def from_words(cls, office: Office, requester: str, text: str) -> Wish:
        """What is known of the wish when only the request's words are: the people and items
        it names (for choosing between options), nothing about whether they want an offer."""
        people = _people_in(office, text) - {requester}
        return cls(
            requester=requester,
            items=tuple(mentioned_item_types(office, text)),
            people=frozenset(people),
            words=text,
        )

    @classmethod
    def from_goal(
        cls,
        office: Office,
        requester: str,
        goal: list[Milestone],
        parts: Sequence[Part] = (),
    ) -> Wish:
        """What the requester wants: the goal's milestones, and the task's ``parts`` for what
        no milestone holds (the operation asked for, where a send-out service sends it)."""
        recipients: list[str] = []
        owners: list[str] = []
        doers: list[str] = []
        items: list[str] = []
        own: list[str] = []
        operations: list[str] = []
        whose: list[tuple[str, str]] = []
        able: set[str] = set()

        def item(item_id: str) -> None:
            type_id, _, owner = item_id.partition(":")
            items.append(type_id)
            if owner not in ("", "*"):
                whose.append((type_id, owner))
            op = office.making(type_id)
            if op is not None and op.input is not None:
                items.append(op.input)  # a printout is of a file
            if owner not in ("", "*") and owner != requester and office.is_person(owner):
                owners.append(owner)
            else:  # nobody's, or a supply a facility keeps for anyone: any one will do
                own.append("mine" if owner == requester else "any")

        for milestone in goal:
            name, args = parse_milestone(milestone)
            able |= able_doers(office, name, args)
            match name:
                case "holds" | "received":
                    recipients.append(args[0])
                    item(args[1])
                case _ if task_kinds.milestone_arity(name) is not None:  # sign, seal, ...
                    item(args[0])
                    doers.extend(args[1:])  # the named doer (a seal's: whoever owns one)
                case "sealed" | "printed" | "copied" | "heated" | "made":
                    item(args[0])
                    operations.extend(_operation_of(office, name, args[0]))
        for part in parts:
            task = part.task(requester, office)
            if task.operation is not None:
                operations.append(task.operation)
        people = {*recipients, *owners, *doers} - {requester}
        return cls(
            requester=requester,
            recipients=tuple(dict.fromkeys(recipients)),
            owners=tuple(dict.fromkeys(owners)),
            doers=tuple(dict.fromkeys(doers)),
            items=tuple(dict.fromkeys(items)),
            own=own[0] if own and not owners else "",
            operations=tuple(dict.fromkeys(operations)),
            destinations=tuple(dict.fromkeys(p.destination for p in parts if p.destination)),
            wants_something=bool(items or recipients),
            people=frozenset(people),
            whose_items=tuple(dict.fromkeys(whose)),
            able=frozenset(able - {requester}),
        )


def _operation_of(office: Office, milestone: str, item_id: str) -> list[str]:
    """The office operation a work milestone ("heated": form) was done by, when the item's type
    says which (the courier of forms, not the charger of headlamps); none when several fit."""
    spec = task_kinds.of_milestone(milestone)
    if spec is None or spec.shape is None:
        return []
    type_id = item_id.partition(":")[0]
    fits = [op.id for op in office.with_shape(spec.shape) if type_id in (op.input, op.product)]
    return fits if len(fits) == 1 else []


def answer(office: Office, wish: Wish, question: str) -> str:
    """What the requester says to ``question``."""
    # "Which item do you mean for me to heat or test or shred?": the works listed are what
    # was asked to be done, not options; the answer names the item
    which_item = _WHICH_ITEM.search(question.lower()) is not None
    options = [] if which_item else _options(question)
    if wish.words is not None:
        return _from_words(office, wish.words, question, options)
    if len(options) >= 2:
        chosen = _choose(office, wish, options)
        if chosen is not None:
            return chosen
    if _is_offer(question):
        return "Yes, please." if _fits(office, wish, question) else "No, thanks."
    if not wish.wants_something:
        return "Nothing, thanks."
    lowered = question.lower()
    if _WHOLE_REQUEST.search(lowered):
        return _plainly(office, wish)
    if _WHERE_TO.search(lowered):
        return f"To {wish.destinations[0]}." if wish.destinations else DONT_KNOW
    if re.search(r"\bwho(m|se)?\b", lowered):
        return _who(office, wish, lowered)
    if re.search(r"\b(which|what)\b", lowered) and wish.items:
        asked = _asked_item(office, wish, lowered)
        if asked is not None:  # "what you want me to do with the charger": whose it is
            return f"{_whose_item(office, wish, asked)}."
        return f"The {_item_name(office, wish.items[0])}."
    return _plainly(office, wish)


DONT_KNOW = "Sorry, I don't know."
_ASKS_SOMEONE = re.compile(r"^\s*shall i ask\b", re.IGNORECASE)
_WHICH_ITEM = re.compile(r"\b(which|what) (item|thing)\b")
_WHOLE_REQUEST = re.compile(
    r"\bwhat (should|shall|can) i do\b|\bwhat do you (need|want)\b|"
    r"\bwhat would you like me to do\b"
)
_WHERE_TO = re.compile(r"\bwhere\b.*\bto\b|\bwhere should i (send|take)\b")
_POSSESSIVE = re.compile(r"\bby '(his|her|their|hers|theirs)'")


def _who(office: Office, wish: Wish, lowered: str) -> str:
    """The person a who-question asks for: whose the item is, who does the work, who gets it,
    or whom a word the assistant could not place meant; both when it asks whose and who."""
    others = [p for p in wish.recipients if p != wish.requester]
    gets = _name(office, others[0]) if others else "Me"
    if "whose" in lowered:
        whose = _whose(office, wish)
        if re.search(r"\bwho should get\b", lowered):  # "Whose book is it, and who should get it?"
            return _whose_and_for_whom(office, wish, "me" if gets == "Me" else gets)
        return whose
    if re.search(r"\b(sign|stamp|seal|do that)", lowered):
        return _name(office, wish.doers[0]) + "." if wish.doers else DONT_KNOW
    if re.search(r"\bwho\b.*\bmean\b", lowered):
        # "who do you mean by 'his'?": whose it is, for a possessive; else who gets it, and
        # of a request for themselves, the owner or doer they named (never "Me.")
        named = [*wish.owners, *wish.doers]
        if named and (_POSSESSIVE.search(lowered) or not others):
            return _name(office, named[0]) + "."
        return gets + "." if others else DONT_KNOW
    return gets + "."


def _asked_item(office: Office, wish: Wish, lowered: str) -> str | None:
    """The item of the wish the question names ("what you want me to do with the charger"),
    or None."""
    named = [
        i
        for i in wish.items
        if re.search(rf"\b{re.escape(_item_name(office, i).lower())}\b", lowered)
    ]
    return named[0] if named else None


def _whose_item(office: Office, wish: Wish, type_id: str) -> str:
    """The item said as its owner would say it: "My stapler", "Brook Tamsin's charger", or
    "The stapler" where it is nobody's in particular."""
    thing = _item_name(office, type_id)
    owners = [o for t, o in wish.whose_items if t == type_id]
    if len(set(owners)) != 1:
        return f"The {thing}"
    if owners[0] == wish.requester:
        return f"My {thing}"
    return f"{_name(office, owners[0])}'s {thing}"


def _whose_and_for_whom(office: Office, wish: Wish, gets: str) -> str:
    """ "It's Zhang Wei's stapler, for Zhou Yan.": the item named whole, so the answer stands
    alone as what they want."""
    thing = _item_name(office, wish.items[0]) if wish.items else "one"
    if wish.owners:
        return f"It's {_name(office, wish.owners[0])}'s {thing}, for {gets}."
    if wish.own == "mine":
        return f"It's my {thing}, for {gets}."
    if wish.own == "any":
        return f"Any {thing} will do, for {gets}."
    return DONT_KNOW


def _whose(office: Office, wish: Wish) -> str:
    if wish.owners:
        return _name(office, wish.owners[0]) + "'s."
    return {"mine": "Mine.", "any": "Anyone's, any will do."}.get(wish.own, DONT_KNOW)


def _is_offer(question: str) -> bool:
    """Whether the question, in its last sentence, offers to do something ("As far as I know,
    Rich has one. Shall I bring you one?")."""
    last = re.split(r"(?<=[.!?])\s+", question.strip())[-1]
    return bool(_OFFER.search(last)) or last.lower().startswith(("is that", "is it ok"))


NOTHING_TO_ADD = "Sorry, I don't know more than I wrote."


def _from_words(office: Office, words: str, question: str, options: list[str]) -> str:
    """The answer of a requester of whom only the request's words are known."""
    if len(options) >= 2:
        chosen = _option_written(words, options)
        if chosen is not None:
            return chosen
    if _is_offer(question):
        return "Yes, please." if _offer_written(office, words, question) else "No, thanks."
    if _WHERE_TO.search(question.lower()):
        # "courier my form to the federation, please": the place they wrote after "to"; "to
        # be dry cleaned" is the work they asked for, no place
        said = re.search(
            r"\bto\s+(?!be\b)(.+?)(?:,?\s+(?:please|thanks?(?: you)?))?[.!?\s]*$", words
        )
        if said is not None:
            return f"To {said.group(1)}."
    return NOTHING_TO_ADD


_MINE = frozenset({"my", "mine", "our", "ours"})


def _offer_written(office: Office, words: str, question: str) -> bool:
    """Whether the offer ("Shall I get your condition report signed by Robin Okonkwo?") is
    what the request's own words ask for ("robin okonkwo needs to sign my condition
    report"): the same people and the same items (at least one), the same work by name (a
    signature, a service; not "bring" for "sign"), and "your" in the offer exactly when
    they wrote "my". Anything else, or an offer
    that names nothing ("Shall I bring you one?"), would be a guess at a wish nobody knows."""
    offer = re.split(r"(?<=[.!?])\s+", question.strip())[-1]
    items = set(mentioned_item_types(office, offer))
    if not items or items != set(mentioned_item_types(office, words)):
        return False
    if _people_in(office, offer) != _people_in(office, words):
        return False
    if set(mentioned_requests(office, offer)) != set(mentioned_requests(office, words)):
        return False
    yours = "your" in _plain_words(offer)
    return yours == bool(_MINE & set(_plain_words(words)))


def _option_written(words: str, options: list[str]) -> str | None:
    """The option whose words the request has most of ("the grace period talk" for "print
    the flyer for the grace period talk"); None when no option stands out."""
    said = set(_plain_words(words))

    def share(option: str) -> float:
        mine = [w for w in _plain_words(option) if w not in _ARTICLES]
        return sum(w in said for w in mine) / len(mine) if mine else 0.0

    scored = sorted((share(o) for o in options), reverse=True)
    if scored[0] == 0 or scored[0] == scored[1]:
        return None
    return next(o for o in options if share(o) == scored[0])


_ARTICLES = frozenset({"the", "a", "an", "my", "your", "one"})


def _plain_words(text: str) -> list[str]:
    return re.findall(r"\w+", text.casefold())


def _options(question: str) -> list[str]:
    """The options a question names: "Do you mean A, or B?" → ["A", "B"]."""
    # only a question offers options: "Please give me the name and address of the school or
    # place." (an office's own words of what its courier asks for) asks for one thing
    sentences = [
        s
        for s in re.split(r"(?<=[.!?])\s+", question)
        if s.rstrip().endswith("?") and (" or " in s or (":" in s and "," in s.partition(":")[2]))
    ]
    if not sentences:
        return []
    body = sentences[-1].strip().rstrip("?.! ")
    body = _LEADS.sub("", body, count=1)
    parts = [p.strip(" ,;:'\"") for p in re.split(r",?\s+or\s+|,\s*", body)]
    return [p for p in parts if p]


def _choose(office: Office, wish: Wish, options: list[str]) -> str | None:
    """The option that fits the wish best; None when none fits better than the others."""

    def score(option: str) -> int:
        people = _people_in(office, option) - {wish.requester}
        # "the month of May": a name that is only a word of a longer phrase counts half for
        # the person, and nothing against them ("May Oduya" is the person for sure)
        named = {p for p in people if _is_the_name(option, office.person(p))}
        items = set(mentioned_item_types(office, option))
        services = _operations_in(office, option)
        return (
            2 * len(named & wish.people)
            + len((people - named) & wish.people)
            - 2 * len(named - wish.people)
            + 2 * len(items & set(wish.items))
            - len(items - set(wish.items))
            + 2 * len(services & set(wish.operations))
            - len(services - set(wish.operations))
        )

    scored = sorted(((score(o), n, o) for n, o in enumerate(options)), key=lambda x: (-x[0], x[1]))
    if len(scored) > 1 and scored[0][0] == scored[1][0]:
        return None
    return scored[0][2] if scored[0][0] >= 0 else None


_FOR_YOU = re.compile(
    r"\b(?:for|to) you\b|\b(?:bring|get|hand|give|fetch|make|buy|send) you\b", re.IGNORECASE
)


def _fits(office: Office, wish: Wish, offer: str) -> bool:
    """Whether an offer ("Shall I bring you Zhang's stapler?") is what the requester wants."""
    if not wish.wants_something:
        return False
    *told, asked = re.split(r"(?<=[.!?])\s+", offer.strip())
    people = _people_in(office, asked) - {wish.requester}
    # "Jo Bell isn't available. Shall I ask Sam Reid instead?": whom it asks to do work
    # wanted of nobody in particular is no one they did not ask for, nor is the one out
    standing_in = wish.able if _ASKS_SOMEONE.search(asked) else frozenset()
    people -= standing_in
    wanted = set(wish.items)
    # "Shall I print your file for Wren?": a word that names a wanted item (the electronic
    # file a printout is made from) and also another ("a box file") is the wanted one
    items = {
        i
        for i in mentioned_item_types(office, offer)
        if i in wanted or not said_only_as_another(office, offer, i, wanted)
    }
    # "Shall I go ahead?" names nothing: yes; an offer that names someone or something they
    # did not ask for: no
    if people - wish.people or items - set(wish.items):
        return False
    # "Shall I print your file for you?" to one who wants it for someone else: no
    if _FOR_YOU.search(asked) and wish.recipients and wish.requester not in wish.recipients:
        return False
    # "As far as I know, Dov and Renée have a headset. Shall I bring you one?": the people
    # before the offer are who has one, not whom it is for; any one will do for a wish of
    # anyone's, and for a wish of someone's own only when no one else is named
    holders = _people_in(office, " ".join(told)) - {wish.requester} - standing_in
    return wish.own == "any" or not holders - wish.people


def _is_the_name(option: str, person: Person) -> bool:
    """Whether an option is only the person's name ("Zhang Wei", "Zhang Wei's")."""
    start, end = _span(option, person)
    rest = f"{option[:start]} {option[end:]}".replace("'s", " ")
    return not [w for w in _plain_words(rest) if w not in _ARTICLES]


def _operations_in(office: Office, text: str) -> set[str]:
    """The office operations an option names by name or verb ("scan", "make tea")."""
    said = f" {' '.join(_plain_words(text))} "
    return {
        op.id
        for op in office.operations
        if any(f" {' '.join(_plain_words(w))} " in said for w in (op.name, *op.verbs))
    }


def _people_in(office: Office, text: str) -> set[str]:
    """The people a text names; of names that overlap ("Anna Mao" holds "Mao", Mao Jun's given
    name), only the person of the longest one."""
    found = {p.id: _mentioned_length(text, p) for p in office.people}
    named = {pid: n for pid, n in found.items() if n}
    if not named:
        return set()
    spans = [(pid, _span(text, office.person(pid))) for pid in named]
    return {
        pid
        for pid, span in spans
        if not any(
            other != pid
            and o[0] <= span[0]
            and span[1] <= o[1]
            and (o[1] - o[0]) > (span[1] - span[0])
            for other, o in spans
        )
    }


def _mentioned_length(text: str, person: Person) -> int:
    span = _span(text, person)
    return span[1] - span[0]


def _span(text: str, person: Person) -> tuple[int, int]:
    """Where the longest of the person's names stands in the text ((0, 0): nowhere)."""
    lowered = text.casefold()
    best = (0, 0)
    for name in (n for n in {person.name, *person.aliases, *person.name.split()} if len(n) > 1):
        for m in re.finditer(rf"(?<!\w){re.escape(name.casefold())}(?!\w)", lowered):
            as_word = " " not in name and is_word_name(language.fold(name))
            if as_word and not re.search(rf"(?<!\w){re.escape(name)}(?!\w)", text):
                continue  # a name that is also a word counts only when written as a name
            if m.end() - m.start() > best[1] - best[0]:
                best = (m.start(), m.end())
    return best


def _name(office: Office, person: str) -> str:
    return office.person(person).name


def _item_name(office: Office, type_id: str) -> str:
    return office.item_type(type_id).name


def _plainly(office: Office, wish: Wish) -> str:
    """What they want, in a few words: "I mean Zhang Wei's stapler, for Min Ho."; a service
    that sends the item out says where: "I mean the form: please courier it to the club."."""
    thing = _item_name(office, wish.items[0]) if wish.items else "it"
    whose = f"{_name(office, wish.owners[0])}'s {thing}" if wish.owners else f"the {thing}"
    sent = [o for o in wish.operations if office.operation(o).sends_out]
    if sent and wish.destinations:
        op = office.operation(sent[0])
        return f"I mean {whose}: please {verb_it(op, wish.destinations[0])}."
    others = [p for p in wish.recipients if p != wish.requester]
    to = f", for {_name(office, others[0])}" if others else ", for me"
    by = f", signed by {_name(office, wish.doers[0])}" if wish.doers else ""
    return f"I mean {whose}{to}{by}."
