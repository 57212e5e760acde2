"""Who is who in a clause: recipient, source, actor and owners, by a priority rule table.

Each person mention gets one role from the first rule of ``PERSON_RULES`` that matches the
words around it ("from Wang" → source, "by Wang" → actor, "to Wang" → recipient, "Wang's
stapler" → an owner of the item that follows). The table is data, read top to bottom: a
rule's place in it is its priority, and the name says why it wins over the rules below it.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, replace
from typing import Literal

from assistantx.agents.symbolic.reading.described_outsider import points_to_outsider
from assistantx.agents.symbolic.reading.gapped_recipient import gapped_recipient
from assistantx.agents.symbolic.reading.indirect_object import is_indirect_object
from assistantx.agents.symbolic.reading.joined_doers import joined_doers
from assistantx.agents.symbolic.reading.joined_owners import joined_owners
from assistantx.agents.symbolic.reading.joined_recipients import Joined, joined_recipients
from assistantx.agents.symbolic.reading.left_with import left_with
from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.obligation import obliged_to
from assistantx.agents.symbolic.reading.occasion import is_occasion, taken_to_a_room
from assistantx.agents.symbolic.reading.part_recipients import after_a_new_object, coordinated
from assistantx.agents.symbolic.reading.source_not_recipient import not_the_source
from assistantx.agents.symbolic.reading.speaker_wants import speaker_wants
from assistantx.agents.symbolic.reading.standing_in import stands_in_for
from assistantx.agents.symbolic.reading.tokens import Token, prev_word
from assistantx.agents.symbolic.reading.vocative import yours_addressed
from assistantx.core import english, language, task_kinds
from assistantx.core.appositive import appositive_preposition
from assistantx.core.asked_to_have import asked_to_have, caused_for
from assistantx.core.receiving_place import (
    MEET_AT,
    PLACE_WORDS,
    Ahead,
    ahead_at,
    lies_there,
    names_receiving_place,
    pronoun_receiving_place,
)
from assistantx.memory.names import TITLES

_DATIVE_VERBS = english.words("dative_verbs")
_OBJECT_PRONOUNS = english.words("object_pronouns")
OTHER_POSSESSIVES = english.words("other_possessives")
_OBJECT_STARTS = english.words("object_starts") | {"one", "some", "another"}
# The words before a person that make them the recipient, the source or the doer.
_TO = frozenset({"to", "for", "with"})
# an article opens a noun phrase of its own: a possessive before it owns nothing in it
_ARTICLES = frozenset({"a", "an", "the", "some", "another", "any"})
# "Min needs scissors": the one who needs the item gets it.
_NEEDS = english.words("need_verbs") | english.words("receive_verbs")
_DIRECT = frozenset({"ask", "have", "let", "tell"})
# The words of the work only a person does (sign, seal): "if Zhang could sign it" makes Zhang
# the doer, a wish about a person that is a request, where "Rich asked for it" is context.
_PERSON_WORK = frozenset(
    w for k in task_kinds.person_kinds() for w in english.word_table("cues")[k]
)
_MODALS = english.words("request_modals")
# "because Rich asked for it", "since Hal is out": a clause that gives a reason; a person in
# it is why, not who gets or does anything.
_REASON = frozenset({"because", "since", "cos", "coz", "cause", "as"})
# "Rich wants it": the thing already asked for, not a new one ("Min needs one" is new)
_BACK_REFERENCES = frozenset({"it", "them", "this", "that", "these", "those"})
# quantifiers English floats after a plural subject: "Wang and Sun both / each sign it"
_FLOATED = frozenset({"both", "each"})


class UnresolvedPronoun(Exception):
    """A possessive pronoun with nobody it could refer to ("bring me his stapler")."""


@dataclass
class Clause:
    mentions: list[Mention]
    cues: set[str] = field(default_factory=set)
    modifiers: set[int] = field(default_factory=set)  # starts of mentions that only modify
    # "print my file and a coffee": a thing made from nothing, split off the work before it
    # with no "too" to say it is asked besides; the whole request is restated and asked first
    restated: bool = False

    def objects(self) -> list[Mention]:
        """The item mentions the request acts on, in text order."""
        return [m for m in self.mentions if m.kind == "item" and m.start not in self.modifiers]


@dataclass
class Roles:
    recipient: list[str] = field(default_factory=list)
    recipient_at: list[int] = field(default_factory=list)  # token start of each recipient
    returned_to: list[str] = field(default_factory=list)  # "back to X": X owns the item
    source: list[str] = field(default_factory=list)
    source_at: list[int] = field(default_factory=list)  # token start of each source
    actor: list[str] = field(default_factory=list)
    bare: list[str] = field(default_factory=list)
    owners: dict[int, str] = field(default_factory=dict)  # item mention start → owner id
    # "for Grace's meeting": whose occasion the thing is for (the recipient if none is named)
    occasion: list[str] = field(default_factory=list)
    occasion_at: list[int] = field(default_factory=list)
    # "bring Wang and Sun a coffee": the groups of people joined as one recipient, each of
    # whom receives (``joined_recipients``; the frame makes or asks, ``for_each``)
    each: list[tuple[str, ...]] = field(default_factory=list)
    # where a recipient was said for the object after it, not the one before: a giving
    # verb's recipient said again after "and", the verb left unsaid ("bring Wang a coffee
    # and *Sun* a water", ``gapped_recipient``), or the subject of a need ("take my stapler
    # to Wang and *Sun* needs a coffee")
    for_next_at: list[int] = field(default_factory=list)
    # "Wang and Sun's files": owner B → the people joined before B's possessive, who own
    # such a thing too (``joined_owners``; the frame does the errand for each, ``each_owner``)
    co_owners: dict[str, list[str]] = field(default_factory=dict)
    # "signed by Wang and Sun": the groups of people joined as the work's doer, each of whom
    # does it (``joined_doers``; the frame makes one task each, ``each_doer``)
    doers: list[tuple[str, ...]] = field(default_factory=list)

    def add_recipient(self, who: str, at: int) -> None:
        self.recipient.append(who)
        self.recipient_at.append(at)

    def source_for(self, item_start: int) -> str | None:
        """Where an item with no owner of its own comes from: the clause's last source,
        unless that source was said of an item before it ("a ruler *from Otto* and a
        stapler": Otto's ruler, the stapler anyone's) and this item comes after it."""
        if not self.source:
            return None
        who, at = self.source[-1], self.source_at[-1]
        bound = any(start < at and owner == who for start, owner in self.owners.items())
        return None if bound and item_start > at else who

    def recipient_between(self, start: int, end: int) -> str | None:
        """The last recipient named in tokens [start, end) ("a coffee *for me* and ...")."""
        found = [
            w for w, at in zip(self.recipient, self.recipient_at, strict=True) if start <= at < end
        ]
        return found[-1] if found else None


@dataclass(frozen=True)
class PersonSite:
    """The words around one person mention."""

    prev: str  # the word before (titles skipped)
    nxt: str  # the word after
    following: Mention | None  # the next mention
    possessive: bool
    back: bool  # "back to Wang"
    subject: bool = False  # a finite verb follows: "Rich asked", "Hal said"
    then: str = ""  # the word after the next one ("it" in "Rich wants it")
    obliged: bool = False  # an obligation to do a person's work follows: "Zhang has to sign"
    stood_in_for: bool = False  # "covering chem for Zhang": whom the speaker stands in for
    to_have: bool = False  # "could Zhang have a stapler": Zhang is asked to be given one
    # "make Zhang a copy", "print Mark my file": after a giving or making verb, before the
    # thing's noun phrase (``indirect_object``)
    indirect: bool = False
    # "bring Wang a coffee and *Sun* a water": the giving verb's recipient again, the verb
    # left unsaid (``gapped_recipient``)
    gapped: bool = False
    # the task word after a possessive, over words that describe it: "Ngozi's *sworn* stamp"
    work_named: Mention | None = None
    occasion: bool = False  # an occasion of theirs follows the possessive: "Grace's meeting"
    ahead: Ahead = field(
        default_factory=Ahead
    )  # the words before ``prev``: "the one" in "the one on Wang's desk"
    # "fetch me some tape? Zhang wants to wrap a parcel": a part of its own, after the one
    # the thing is handed to was named, telling what the person wants to do (``_later_use``)
    later_use: bool = False

    @property
    def at_place(self) -> bool:
        """ "Wang's desk": the person's place, not something they own."""
        return self.possessive and bool(self._place_word())

    def _place_word(self) -> str:
        """The place word right after the possessive: a plain word ("desk"), or one the
        office also names a place by ("Mercy's bench" where a workstation is the "Checking
        bench"): said after a colleague's possessive it is their place all the same."""
        f = self.following
        if f is None:
            return ""
        if f.kind == "word" and f.ids[0] in PLACE_WORDS:
            return f.ids[0]
        said = f.text.lower()
        return said if f.kind == "place" and said in PLACE_WORDS else ""

    @property
    def work(self) -> Mention | None:
        """The task word the possessive names: right after it, or after words that describe
        it ("Ngozi's wet signature", ``work_named``)."""
        if self.work_named is not None:
            return self.work_named
        f = self.following
        return f if f is not None and f.kind == "cue" else None

    @property
    def place(self) -> str:
        """The place word after a possessive ("desk" in "Wang's desk"), else ""."""
        return self._place_word() if self.possessive else ""


Slot = Literal["recipient", "returned", "source", "actor", "bare", "owner", "context", "occasion"]


@dataclass(frozen=True)
class PersonRule:
    name: str
    applies: Callable[[PersonSite], bool]
    slot: Slot


# Highest priority first; the first rule that applies gives the person's role.
PERSON_RULES: tuple[PersonRule, ...] = (
    PersonRule(
        "the one on Wang's desk, the book that's on Wang's desk: where it lies, the source",
        lambda s: s.at_place and s.prev in MEET_AT and lies_there(s.ahead),
        "source",
    ),
    PersonRule(
        "at Wang's desk: met there",
        lambda s: s.at_place and names_receiving_place(s.prev, s.place, s.ahead),
        "recipient",
    ),
    PersonRule("from Wang's desk: the source", lambda s: s.at_place and s.prev == "from", "source"),
    PersonRule("Wang's desk: named, no role yet", lambda s: s.at_place, "bare"),
    PersonRule(
        "Wang's signature: Wang signs",
        lambda s: (
            s.possessive
            and s.work is not None
            and any(
                k in s.work.ids and not task_kinds.needs_tool(k) for k in task_kinds.person_kinds()
            )
        ),
        "actor",
    ),
    PersonRule(
        "for Grace's meeting: whose occasion it is receives, unless another is named",
        lambda s: s.possessive and s.prev == "for" and s.occasion,
        "occasion",
    ),
    PersonRule("Wang's stapler: an owner of the item", lambda s: s.possessive, "owner"),
    PersonRule(
        "because Rich ...: the reason, not a party",
        lambda s: s.prev in _REASON,
        "context",
    ),
    PersonRule(
        "Rich wants it (on the board): a wish about what was asked, not a recipient",
        lambda s: s.nxt in _NEEDS and s.then in _BACK_REFERENCES,
        "context",
    ),
    PersonRule(
        "fetch me tape? Zhang wants to wrap a parcel: Zhang's use of it, not a recipient",
        lambda s: s.later_use,
        "context",
    ),
    PersonRule("Zhang has to / must sign: the doer", lambda s: s.obliged, "actor"),
    PersonRule(
        "could Min have / let Min borrow scissors: the one asked for receives",
        lambda s: s.to_have and not s.possessive,
        "recipient",
    ),
    PersonRule(
        "Min needs / gets scissors: the one in need receives",
        lambda s: s.nxt in _NEEDS,
        "recipient",
    ),
    PersonRule("from Wang: the source", lambda s: s.prev == "from", "source"),
    # "get it off her", "borrow a pen off Zhang": "off" as people say "from" of a person
    PersonRule("off Wang: the source", lambda s: s.prev == "off", "source"),
    PersonRule("by Wang: the doer", lambda s: s.prev == "by", "actor"),
    PersonRule(
        "back to Wang: the owner, given back", lambda s: s.prev == "to" and s.back, "returned"
    ),
    PersonRule(
        "covering for Fen, standing in for Fen: why the speaker asks, not a recipient",
        lambda s: s.stood_in_for,
        "context",
    ),
    PersonRule("to / for / with Wang: the recipient", lambda s: s.prev in _TO, "recipient"),
    PersonRule(
        "Wang to sign, ask Wang: the doer", lambda s: s.nxt == "to" or s.prev in _DIRECT, "actor"
    ),
    PersonRule(
        "if Wang could sign it, Wang would sign it: the doer of a person's work",
        lambda s: s.nxt in _PERSON_WORK or (s.nxt in _MODALS and s.then in _PERSON_WORK),
        "actor",
    ),
    PersonRule(
        "give Wang a stapler: the recipient",
        lambda s: s.prev in _DATIVE_VERBS and s.following is not None and s.following.kind != "cue",
        "recipient",
    ),
    PersonRule(
        "make Zhang a copy, print Mark my file: whom the thing made is for",
        lambda s: s.indirect,
        "recipient",
    ),
    PersonRule(
        "bring Wang a stapler and Sun a pen: Sun is whom the unsaid verb gives the pen",
        lambda s: s.gapped,
        "recipient",
    ),
    PersonRule(
        "Rich asked for it, Hal said so: the subject of a statement, not a party",
        lambda s: s.subject,
        "context",
    ),
    PersonRule("otherwise: named, no role yet", lambda s: True, "bare"),
)


def person_rule(site: PersonSite) -> PersonRule:
    """The first rule of ``PERSON_RULES`` that applies (the last one always does)."""
    return next(r for r in PERSON_RULES if r.applies(site))


def _next_item_start(ms: list[Mention], n: int, default: int) -> int:
    """Where the first item named after mention ``n`` starts ("could Min have a *stapler*")."""
    return next((x.start for x in ms[n + 1 :] if x.kind == "item"), default)


def _ahead_of(tokens: Sequence[Token], start: int) -> Ahead:
    """The two words before the one before token ``start`` (titles skipped), within its
    sentence and phrase: "the", "one" in "the one on Dr Wang's desk"."""
    k = start - 1
    while k >= 0 and tokens[k].word in TITLES:
        k -= 1
    return ahead_at(tokens, k)


def person_role(tokens: Sequence[Token], ms: list[Mention], n: int, who: str, roles: Roles) -> None:
    m = ms[n]
    prev = prev_word(tokens, m.start)
    if not m.possessive and prev not in _TO:
        # "for the cover teacher, Ms Nguyen": the name is the receiving phrase's person
        prev = appositive_preposition(tokens, m.start, m.end) or prev
    # "Wang and Sun both sign it": a quantifier floated after the subject is read past
    after = m.end + (m.end + 1 < len(tokens) and tokens[m.end].word in _FLOATED)
    site = PersonSite(
        prev=prev,
        ahead=_ahead_of(tokens, m.start),
        nxt=tokens[after].word if after < len(tokens) else "",
        following=ms[n + 1] if n + 1 < len(ms) else None,
        possessive=m.possessive,
        back=m.start >= 2 and tokens[m.start - 2].word == "back",
        subject=after < len(tokens) and language.is_finite_verb(tokens[after].word),
        then=tokens[after + 1].word if after + 1 < len(tokens) else "",
        obliged=obliged_to([t.word for t in tokens], m.end, _PERSON_WORK),
        stood_in_for=stands_in_for([t.word for t in tokens], m.start - 1),
        to_have=asked_to_have(
            prev_word(tokens, m.start),  # "could Mr K have": the title skipped
            [t.word for t in tokens[m.end : _next_item_start(ms, n, m.end + 3)]],
        )
        # "could Linh get my report printed": the thing made for her
        or caused_for(prev_word(tokens, m.start), [t.word for t in tokens[m.end : m.end + 9]]),
        indirect=is_indirect_object(tokens, ms, n, prev),
        gapped=gapped_recipient(tokens, ms, n),
        later_use=_later_use(tokens, m.start, after),
    )
    if m.possessive:
        occasion = is_occasion(tokens, site.following, m.end)
        site = replace(site, work_named=_work_after(tokens, ms, n), occasion=occasion)
    match person_rule(site).slot:
        case "recipient":
            roles.add_recipient(who, m.start)
            if site.gapped or site.nxt in _NEEDS:
                roles.for_next_at.append(m.start)
        case "returned":  # "take the stapler back to Zhang": Zhang's, and Zhang gets it
            roles.add_recipient(who, m.start)
            roles.returned_to.append(who)
        case "source":
            roles.source.append(who)
            roles.source_at.append(m.start)
        case "actor":
            roles.actor.append(who)
        case "bare":
            roles.bare.append(who)
        case "owner":
            pass  # attached to the item that follows (``owner_of``)
        case "context":
            pass  # why the request was made ("because Rich asked"): no role in it
        case "occasion":
            roles.occasion.append(who)
            roles.occasion_at.append(m.start)


# "Zhang wants to borrow / have / use it": taking the thing, which makes Zhang its recipient
_TAKING = frozenset({"have", "get", "borrow", "use", "keep", "take", "grab", "hold", "receive"})
_TAKEN = _BACK_REFERENCES | _ARTICLES | {"one", "mine", "yours"}


def _later_use(tokens: Sequence[Token], start: int, after: int) -> bool:
    """Whether the person at ``start`` opens a part of their own, after a request that hands
    the thing to the speaker, and is said to want to do something other than take the thing
    ("fetch me some tape? Zhang wants to wrap a parcel later"): why it is asked for, a
    colleague's purpose, never whom it is handed to (fix201b class 5: before, Zhang was read
    as the recipient, and the run sent Zhang the locker's code)."""
    t = tokens[start]
    if start == 0 or not (t.opens or t.after_pause):
        return False
    said = [x.word for x in tokens[after : after + 4]]
    if len(said) < 3 or said[0] not in _NEEDS or said[1] != "to":
        return False
    if said[2] in _TAKING and (len(said) == 3 or said[3] in _TAKEN):
        return False  # "Zhang wants to borrow it": Zhang takes it ("to take notes" does not)
    return _speaker_receives([x.word for x in tokens[:start]])


# "fetch me", "for me", "to us": the speaker named as whom the thing is handed to
_SPEAKER_OBJECTS = frozenset({"me", "us"})


def _speaker_receives(words: Sequence[str]) -> bool:
    """Whether ``words`` name the speaker as whom the thing is handed to ("fetch me some
    tape", "... for me", "I need some tape")."""
    return speaker_wants(words) or any(
        w in _SPEAKER_OBJECTS and n > 0 and (words[n - 1] in _DATIVE_VERBS or words[n - 1] in _TO)
        for n, w in enumerate(words)
    )


# How many describing words may stand between a possessive and the work it names ("Ngozi's
# sworn stamp", "Hal's official wet signature").
_WORK_DESCRIBED = 2


def _work_after(tokens: Sequence[Token], ms: list[Mention], n: int) -> Mention | None:
    """The task word a possessive names, right after it or after words that describe it
    ("Ngozi's *sworn* stamp"): words of no other phrase (no article, preposition, pronoun,
    place word or pause between)."""
    for k in range(n + 1, min(len(ms), n + 2 + _WORK_DESCRIBED)):
        x = ms[k]
        if x.kind == "cue":
            return x
        t = tokens[x.start]
        if x.kind != "word" or t.opens or t.after_pause or t.possessive:
            return None
        if t.word in _PHRASE_ENDS or t.word in PLACE_WORDS:
            return None
    return None


_COURTESY_AFTER = frozenset({"please", "pls", "plz", "thanks", "thx", "ta", "cheers", "x"})


def _a_favour(
    tokens: Sequence[Token], ms: Sequence[Mention], n: int, roles: Roles, requester: str
) -> bool:
    """ "... to Zhang for me (please)": a "for me" that ends the clause after a colleague
    already named after "to" asks a favour; it names no second recipient. With a new object
    between ("my stapler to Wang and a coffee for me") it is that object's recipient."""
    if any(tokens[m.start].word not in _COURTESY_AFTER for m in ms[n + 1 :]):
        return False
    return any(
        who != requester
        and prev_word(tokens, at) == "to"
        and not after_a_new_object(ms, at, ms[n].start)
        for who, at in zip(roles.recipient, roles.recipient_at, strict=True)
    )


def clause_roles(
    tokens: Sequence[Token],
    clause: Clause,
    requester: str,
    last_person: list[str],
    *,
    addressed: str | None = None,
    not_meant: frozenset[str] = frozenset(),
    taken_from: Sequence[str] = (),
    message_named: Sequence[str] = (),
    outsider_said: bool = False,
) -> Roles:
    """The roles of everyone a clause names; ``last_person`` collects who was named so far
    (for "him", "her"); ``addressed``: the colleague the message opens by addressing (whose
    "your" is theirs, ``vocative``); ``not_meant``: colleagues a "him"/"her" that receives
    cannot mean (the owner of the thing handed to them, ``frames._besides_owners``);
    ``taken_from``: whom an earlier clause took the thing this one hands on from ("get it from
    June and bring it to her": not June); ``message_named``: the colleagues the whole message
    names, for a "them both" that follows no name of the request's own words;
    ``outsider_said``: the whole message describes an outsider and names no colleague
    (``described_outsider.outsider_only``), whom a "for him" with no one named means."""
    roles = Roles()
    ms = clause.mentions
    groups = joined_recipients(tokens, ms, requester, last_person or message_named)
    grouped = frozenset(at for g in groups for at in g.pronouns)
    joined = joined_owners(tokens, ms)
    for n, m in enumerate(ms):
        if m.start in grouped:
            continue  # "bring him and Sun a coffee": "him" is one of a group (below)
        if m.kind == "person" and m.start in joined:
            # "bring me Wang and Sun's files": Wang owns one too, no party of the errand
            roles.co_owners.setdefault(joined[m.start], []).append(m.ids[0])
            last_person.append(m.ids[0])
            continue
        if m.kind == "person":
            who = m.ids[0]
            last_person.append(who)
            person_role(tokens, ms, n, who, roles)
        elif m.kind == "self":
            word = tokens[m.start].word
            if word in ("my", "mine"):
                continue
            prev = prev_word(tokens, m.start)
            if prev == "for" and _a_favour(tokens, ms, n, roles, requester):
                continue  # "take my stapler to Zhang for me": Zhang gets it, as a favour to me
            if prev in _TO or prev in _DATIVE_VERBS:
                roles.add_recipient(requester, m.start)
            elif gapped_recipient(tokens, ms, n):  # "get Pat a tea and me a highlighter"
                roles.add_recipient(requester, m.start)
                roles.for_next_at.append(m.start)
        elif m.kind == "pronoun" and _at_their_place(tokens, m):
            # "Priya wants a stapler, leave one at her desk": she receives it there (the
            # consent guard reads the same words with the same rule)
            others = [x for x in last_person if x != requester and x not in not_meant]
            if len(set(others)) != 1:
                raise UnresolvedPronoun(m.text)
            roles.add_recipient(others[-1], m.start)
        elif m.kind == "pronoun" and _asked_to_do_person_work(tokens, m):
            # "send my rundown to Dawn and get her to sign my log sheet": the one colleague
            # named before does the work; with none or several named, whom is asked
            others = [x for x in last_person if x != requester]
            if len(set(others)) != 1:
                raise UnresolvedPronoun(m.text)
            roles.actor.append(others[-1])
        elif m.kind == "pronoun" and tokens[m.start].word in _OBJECT_PRONOUNS:
            following = ms[n + 1] if n + 1 < len(ms) else None
            others = [x for x in last_person if x != requester and x not in not_meant]
            possessive_form = tokens[m.start].word in OTHER_POSSESSIVES
            owns_next = (
                following is not None
                and following.kind == "item"
                and not _article_between(tokens, m, following)
            )
            if owns_next and possessive_form:
                continue  # "her stapler": a possessive ("her a stapler": whom it goes to)
            prev = prev_word(tokens, m.start)
            # "to her", "for him", and "drop it with her": whom the thing is handed to
            handed = prev in ("to", "for") or left_with([t.word for t in tokens], m.start)
            # "take her my ice pack", "bring her some": she receives (not "forward them to")
            dative = (
                prev in _DATIVE_VERBS
                and following is not None
                and _object_start(tokens, following)
                and not coordinated(tokens, m)  # "bring them and a coffee": two objects
            ) or is_indirect_object(tokens, ms, n, prev)
            # "bring Pat a tea and her a ruler": the giving verb's recipient again, unsaid
            gapped = gapped_recipient(tokens, ms, n)
            dative = dative or gapped
            if gapped:  # "bring Pat a tea and her a ruler": "her" is someone besides Pat
                others = [x for x in others if x not in roles.recipient]
            if handed or dative:
                # "take it from Pat to her": not Pat, the one it is taken from
                others = not_the_source(others, [*taken_from, *roles.source], tokens, m.start)
            outsider = outsider_said or points_to_outsider(tokens, m.start)
            # the speaker as the one it is handed to: "get *me* a coffee for him", "*I need*
            # a coffee for him" ("bring a coffee for him" names nobody who takes it: asked)
            mine = requester in roles.recipient or speaker_wants(
                [t.word for t in tokens[: m.start]]
            )
            if prev == "for" and not dative and not others and outsider and mine:
                # "a client's visiting from Dublin, get me a coffee for him": him is the
                # outsider; only people of the office are handed anything, so the requester
                # receives it to pass on
                if requester not in roles.recipient:
                    roles.add_recipient(requester, m.start)
                continue
            if (handed or dative) and len(set(others)) != 1:
                # never the requester by default, nor the last of two people named ("Thảo's
                # on the ladder and Ivy's busy, take her a stool": whom?)
                raise UnresolvedPronoun(m.text)
            if handed or dative:
                roles.add_recipient(others[-1], m.start)
                if gapped:
                    roles.for_next_at.append(m.start)
        elif m.kind == "item":
            owner = owner_of(
                tokens,
                ms,
                n,
                requester,
                last_person,
                addressed=addressed,
                outsider_said=outsider_said,
            )
            if owner is not None:
                roles.owners[m.start] = owner
    for group in groups:
        if not group.people:  # "Wang is in, bring them both a water": both of whom?
            raise UnresolvedPronoun("them")
        _add_group(roles, group)
    busy = [*roles.recipient, *roles.source, *roles.returned_to]
    roles.doers = joined_doers(tokens, ms, roles.actor, busy)
    grouped_doers = {who for g in roles.doers for who in g}
    roles.bare = [who for who in roles.bare if who not in grouped_doers]
    if roles.occasion and not roles.recipient and taken_to_a_room(tokens, ms):
        # "take a ruler to the lounge for Mark's workshop": Mark, as nobody else receives it
        roles.add_recipient(roles.occasion[-1], roles.occasion_at[-1])
    return roles


def _add_group(roles: Roles, group: Joined) -> None:
    """Each of a group joined as one recipient receives: added where not read so already, the
    recipients kept in text order (the last said is the clause's recipient), none of them
    left a bare name."""
    pairs = dict.fromkeys(zip(roles.recipient, roles.recipient_at, strict=True))
    pairs.update(dict.fromkeys(zip(group.people, group.at, strict=True)))
    ordered = sorted(pairs, key=lambda p: p[1])
    roles.recipient = [who for who, _ in ordered]
    roles.recipient_at = [at for _, at in ordered]
    roles.bare = [who for who in roles.bare if who not in group.people]
    roles.each.append(group.people)


# A person the office does not know, said by what they are ("the client", "our auditor", "the
# visitors"): the antecedent of a possessive pronoun after it when no colleague is named
_OUTSIDER_NOUNS = (english.words("outsider_nouns") | english.words("role_nouns")) - {
    "someone",
    "somebody",
    "person",
    "people",
}
_OUTSIDER_DETERMINERS = frozenset(
    {"the", "a", "an", "our", "my", "your", "this", "that", "these", "those", "some"}
)


# What an outsider is said to want, the reason a request is made ("the client *wants* a
# copy", "the auditors *would like* one", "the visitor *asked* for it")
_OUTSIDER_WANTS = english.words("need_verbs") | {"like", "asked", "asks", "requested"}
_WANT_NEAR = 3  # "the client really would like"


def _outsider_before(tokens: Sequence[Token], at: int) -> bool:
    """Whether an outsider, said by a determiner and a noun of a kind of person in a clause
    after the request, is said to want something before ``at`` ("photocopy my contract, the
    client wants a copy for *their* files"): the reason for the request, whose "their" is
    the outsider's."""
    for k in range(1, at):
        word = tokens[k].word
        singular = word[:-1] if word.endswith("s") else word
        det = tokens[k - 1]
        if det.word not in _OUTSIDER_DETERMINERS:
            continue
        if k - 1 == 0 or not (det.after_pause or det.opens or tokens[k - 2].word in _REASON):
            continue  # said after the request, as its reason ("..., the client wants ...")
        if word not in _OUTSIDER_NOUNS and singular not in _OUTSIDER_NOUNS:
            continue
        if any(t.word in _OUTSIDER_WANTS for t in tokens[k + 1 : min(at, k + 1 + _WANT_NEAR)]):
            return True
    return False


def _outsider_subject(
    tokens: Sequence[Token], at: int, people_at: frozenset[int] = frozenset()
) -> bool:
    """Whether the possessive at ``at`` ("their") is said of the outsider who opens its
    clause as the subject of a want or need right before it: "a visitor needs their pass
    signed off", "customer needs their receipt stamped", "my patient needs their form
    copied". The outsider is named by a kind of person, after a determiner or bare, or is a
    plural of things or creatures (``_things_subject``); ``people_at``: where colleagues
    are named, who are never such a subject."""
    start = max((k for k in range(at) if tokens[k].opens or tokens[k].after_pause), default=0)
    k = start + 1 if tokens[start].word in _OUTSIDER_DETERMINERS else start
    if k >= at:
        return False
    word = tokens[k].word
    singular = word[:-1] if word.endswith("s") else word
    if word not in _OUTSIDER_NOUNS and singular not in _OUTSIDER_NOUNS:
        return _things_subject(tokens, k, at, people_at)
    between = [t.word for t in tokens[k + 1 : at]]
    return 0 < len(between) <= _WANT_NEAR and between[-1] in _OUTSIDER_WANTS


# how many words a plural subject's phrase may run to before its need ("the new tangs in QT")
_SUBJECT_WORDS = 7
# words that are no part of a thing's or creature's noun phrase
_NO_SUBJECT = (
    english.words("pronouns") | english.words("subject_pronouns") | english.words("self_words")
)


def _things_subject(tokens: Sequence[Token], k: int, at: int, people_at: frozenset[int]) -> bool:
    """Whether the clause opening at ``k`` is a plural noun phrase of no colleague, then a
    want or need right before ``at``: "the new tangs in QT need their treatment sheet
    stamped", "the seedlings need their labels printed". Creatures and things the speaker
    looks after are nobody of the office, so their paper is in the speaker's hands."""
    if at - 1 <= k or tokens[at - 1].word not in _OUTSIDER_WANTS or at - 1 - k > _SUBJECT_WORDS:
        return False
    phrase = range(k, at - 1)
    if any(i in people_at or tokens[i].word in _NO_SUBJECT for i in phrase):
        return False
    return any(_plural_noun(tokens[i].word) for i in phrase)


def _plural_noun(word: str) -> bool:
    """A plural the dictionary knows as a noun ("tangs", "seedlings")."""
    return word.endswith("s") and language.is_plural_noun(word)


def _outsiders_in_hand(
    tokens: Sequence[Token], at: int, end: int, people_at: frozenset[int] = frozenset()
) -> bool:
    """Whether "their" at ``at`` is the outsider's who opens its clause (``_outsider_subject``)
    and the thing it owns, ending at ``end``, is to be worked on: a participle of the work
    after it ("their pass signed off", "their form copied") or what it should bear ("their
    receipt with the stamp on it"); never a thing wanted back ("their stapler back")."""
    if tokens[at].word != "their" or end >= len(tokens):
        return False
    after = tokens[end].word
    worked = after == "with" or language.is_past_participle(after)
    return worked and _outsider_subject(tokens, at, people_at)


def owner_of(
    tokens: Sequence[Token],
    ms: list[Mention],
    n: int,
    requester: str,
    last_person: list[str],
    *,
    addressed: str | None = None,
    outsider_said: bool = False,
) -> str | None:
    m = ms[n]
    # "my / Zhang's / his [own] stapler": a possessive up to two words before the item
    for k in range(n - 1, max(-1, n - 3), -1):
        p = ms[k]
        if _article_between(tokens, p, m):
            break  # "take her a kick stool": "her" is whom it goes to, not whose it is
        if p.kind == "self" and p.possessive:
            return requester
        if p.kind == "person" and p.possessive:
            return p.ids[0]
        if p.kind == "pronoun" and p.possessive:
            others = [x for x in last_person if x != requester]
            for_theirs = prev_word(tokens, p.start) == "for" and (
                outsider_said or points_to_outsider(tokens, p.start)
            )
            people_at = frozenset(
                i for x in ms if x.kind == "person" for i in range(x.start, x.end)
            )
            if not others and _outsiders_in_hand(tokens, p.start, m.end, people_at):
                # "a visitor needs their pass signed off": the outsider's thing, to be worked
                # on, is in the speaker's hands (no colleague's to ask about)
                return requester
            if not others and (for_theirs or _outsider_before(tokens, p.start)):
                # "..., the client wants a copy for their files", "Mrs Okafor is coming in
                # at 3. I need a mount for her etching": theirs, an outsider's, what the
                # work is for; no colleague to ask about
                return None
            if not others:  # "his stapler" with nobody named before: whose?
                raise UnresolvedPronoun(p.text)
            return others[-1]
        if p.kind not in ("word", "item"):  # "Wang's report file": a compound noun
            break
    if addressed != requester and (yours := yours_addressed(tokens, m, addressed)):
        return yours  # "Otto, could the robot bring me your ruler?": Otto's
    described = _described_owner(tokens, ms, n, requester)
    if described is not None:
        return described
    # "the stapler of Zhang" / "a stapler from Zhang"
    if n + 2 < len(ms) + 1 and n + 1 < len(ms):
        nxt = tokens[m.end].word if m.end < len(tokens) else ""
        after = ms[n + 1]
        if nxt in ("of", "from") and after.kind == "word" and n + 2 < len(ms):
            after = ms[n + 2]
        if nxt in ("of", "from") and after.kind == "person":
            return after.ids[0]
        if nxt == "of" and after.kind == "self" and tokens[after.start].word in ("mine", "ours"):
            return requester  # "these headphones of mine"
    return None


# Words that end a noun phrase when read backwards from its head: whatever stands before
# them belongs to another phrase ("Bea's ladder and the folder", "Hamid's, for the folder").
_PHRASE_ENDS = (
    _ARTICLES
    | english.words("party_prepositions")
    | english.words("clause_joins")
    | english.words("clause_breaks")
    | english.words("determiners")
    | english.words("self_words")
    | english.words("pronouns")
    | english.words("subject_pronouns")
)
# How many describing words may stand between a possessive and its item ("Omar's big blue
# project folder", "Ms Lan's laundry rota file").
_DESCRIBING_WORDS = 4


def _described_owner(
    tokens: Sequence[Token], ms: list[Mention], n: int, requester: str
) -> str | None:
    """ "Ms Lan's laundry rota file", "Omar's big blue project folder": the possessive
    before words that describe the item (adjectives, nouns the office does not know, a
    place's name used as a modifier, the item's own words) owns it. Any word that starts
    another phrase (an article, a preposition, "and", a pronoun), a task word, a person
    named without "'s", a second possessive or punctuation inside the phrase ends it."""
    m = ms[n]
    at = {x.start: x for x in ms}
    inside = {k for x in ms for k in range(x.start + 1, x.end)}
    k = m.start - 1
    while k >= 0 and m.start - 1 - k <= _DESCRIBING_WORDS:
        if k in inside:
            k -= 1
            continue
        here = at.get(k)
        if here is not None and here.possessive and here.kind in ("person", "self"):
            return requester if here.kind == "self" else here.ids[0]
        if here is not None and here.kind not in ("word", "item", "place", "facility"):
            return None
        token = tokens[k]
        if token.possessive or token.word in _PHRASE_ENDS or token.opens:
            return None
        k -= 1
    return None


def recipient_of(objects: list[Mention], k: int, roles: Roles, default: str) -> str:
    """Whom one of several objects is for: a "for/to X" right after it ("a coffee for me and
    some water for Wang"), else the recipient of a verb left unsaid right before it ("... and
    Sun a water"), else one named before all objects ("get me X and Y"), else the clause's
    recipient ("take my book and my pen to Wang")."""
    m = objects[k]
    end = objects[k + 1].start if k + 1 < len(objects) else 1 << 30
    # "bring Wang a coffee and Sun a water", "... and Sun needs a coffee": a recipient said
    # for the object after it is that object's, never the object's before it
    gapped = [
        w
        for w, at in zip(roles.recipient, roles.recipient_at, strict=True)
        if at in roles.for_next_at and (objects[k - 1].end if k else 0) <= at < m.start
    ]
    after = [
        w
        for w, at in zip(roles.recipient, roles.recipient_at, strict=True)
        if m.end <= at < end and at not in roles.for_next_at
    ]
    return (
        (after[-1] if after else None)
        or (gapped[-1] if gapped else None)
        or roles.recipient_between(0, objects[0].start)
        or default
    )


def _asked_to_do_person_work(tokens: Sequence[Token], m: Mention) -> bool:
    """Whether an object pronoun is the one asked to do a person's work ("get *her* to sign
    it", "ask *him* to stamp my form"): "to" and the work's word right after it."""
    after = [t.word for t in tokens[m.end : m.end + 2]]
    return (
        m.end == m.start + 1
        and tokens[m.start].word in _OBJECT_PRONOUNS - {"them"}
        and after[:1] == ["to"]
        and after[1:] != []
        and after[1] in _PERSON_WORK
    )


def _at_their_place(tokens: Sequence[Token], m: Mention) -> bool:
    """ "at her desk", "in his office": a possessive pronoun naming a person's own place."""
    after = tokens[m.end].word if m.end < len(tokens) and not tokens[m.end].opens else ""
    word, before = tokens[m.start].word, prev_word(tokens, m.start)
    return pronoun_receiving_place(before, word, after, _ahead_of(tokens, m.start))


def _article_between(tokens: Sequence[Token], a: Mention, b: Mention) -> bool:
    """Whether an article stands between two mentions: "her a stool" is two phrases."""
    return any(t.word in _ARTICLES for t in tokens[a.end : b.start])


def _object_start(tokens: Sequence[Token], m: Mention) -> bool:
    """Whether a mention opens a verb's object ("my", "some", "a", "the stapler", "Rich's")."""
    return (
        m.kind in ("self", "item")
        or (m.kind == "person" and m.possessive)
        or tokens[m.start].word in _OBJECT_STARTS
    )
