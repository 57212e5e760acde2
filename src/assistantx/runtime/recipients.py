"""Who the requester named as a recipient or a doer: the people a hand-over may go to.

The consent guard lets a code (or a file) go to a person other than the requester, an owner
or a keeper only when the requester named that person *in a receiving role*. A name that
merely stands somewhere in their words does not count: "... because Rich asked for it",
"Rich wants it up on the board" and "Rich's form" name Rich as the reason, a wisher or an
owner, never as the one who gets the item. The roles are read from the requester's own
words alone (never from a reasoner's reading), by the position of the name:

- after a preposition of receiving: "to Hal", "for Hal", "with Hal" ("leave it with Hal"),
  and a place of theirs: "on Hal's desk", "at her desk" (``core.receiving_place``, the rule
  the reader reads the recipient with);
- right after a giving verb, in any of its forms: "bring Hal a thermometer", "lent Hal ...";
- as a doer: "by Hal", "get Hal to sign", "Hal to sign it", "could Hal sign it?", "would Hal
  be able to stamp it?";
- asked to be given it: "could Hal have a thermometer?", "Hal could do with one"
  (``core.asked_to_have``, the rule the reader reads the recipient with);
- picked out as the one who needs it: "it's Hal who needs the copy, not me" (the cleft says
  who, where a plain "Hal wants it" may only be a wish);
- a pronoun in one of those places ("take her my ice pack") when exactly one person the
  requester named is neither an owner ("May's ice pack") nor the requester, and such a
  pronoun as the first of a verb's two objects, whatever the verb ("Hal needs a stapler,
  can you sort him one?", "find her one");
- a reply in their own chat that is just a name ("Hal Brooks.", "to Hal, please"): the
  answer to "Who should get it?";
- a "Shall I ...?" of the assistant in the requester's chat, answered yes by the requester,
  in which the name stands in one of those places ("Shall I bring Hal a thermometer?");

and, for work done by hand (sign, seal), ``named_doers``: the doer of the reader's own frame
of the request ("Hal needs to sign my form, can you sort it?": Hal signs), the reading the
symbolic reasoner plans with, so the guard never refuses the hand-over that reading asked
for. The frame adds only people the requester's own words name, and only as doers: the work
done by hand puts the item back in the locker, whereas a recipient keeps it, so a recipient
is still read from the words alone (a frame that misreads "May wants it on the board, my
clipboard is for Rich" as giving it to May must not make May a party). The one exception is a
thing made at the requester's request (``made_for``: a copy of their file, a printout, a
coffee): nobody owns it but whom it is made for, so the recipient of the reader's frame, whom
the requester's words name, may collect it ("Lin needs a copy of my report").
"""

from __future__ import annotations

import functools
import re
import weakref
from dataclasses import dataclass

from assistantx.agents.symbolic.answers import stance
from assistantx.agents.symbolic.reading.abbreviations import undotted
from assistantx.agents.symbolic.reading.exact_spelling import own_spellings, spelled_by
from assistantx.agents.symbolic.reading.near_possessive import near_possessives
from assistantx.agents.symbolic.reading.placed_thing import placed_things
from assistantx.agents.symbolic.reading.seated_subject import SeatedSubject
from assistantx.agents.symbolic.reading.surnames import family_names
from assistantx.core import english, language, name_parts
from assistantx.core.appositive import appositive_preposition
from assistantx.core.asked_to_have import asked_to_have, caused_for
from assistantx.core.handed_owner import carried_to
from assistantx.core.name_reading import is_word_name, read_name, slot_at
from assistantx.core.needed_instead import needs_the_thing
from assistantx.core.occasion_noun import occasion_noun
from assistantx.core.office import Office
from assistantx.core.ports.messenger import ChatRef
from assistantx.core.ranks import rank_titles
from assistantx.core.receiving_place import (
    Ahead,
    ahead_at,
    names_receiving_place,
    pronoun_receiving_place,
)
from assistantx.core.task_schema import Task, TaskFrame, operation_of
from assistantx.core.wanted_to_have import REACH, wants_to_have
from assistantx.memory.short_term import ShortTermMemory
from assistantx.runtime.handed_over import subject_asked_to_have, taken_across
from assistantx.runtime.wanted_own import handed_on, wants_own_thing, wishes_said

_TO = frozenset({"to", "for", "with", "towards", "toward", "onto"})
_BY = frozenset({"by"})
_DOER_VERBS = frozenset({"get", "ask", "have", "let", "make"})
# A question asked of a colleague's work: "could Hal sign it?", "can Hal stamp my form?"
_MODALS = frozenset({"could", "can", "would", "will", "might"})
_DOING = frozenset({"sign", "seal", "stamp", "chop", "initial", "approve", "countersign"})
_GIVE = english.words("dative_verbs") | english.words("handing_verbs")
_TITLES = english.words("titles") - {"a", "an", "the", "our"}
# titles that name a role ("the manager"), not titles of address ("Dr.", "Ms")
_ADDRESS_TITLES = frozenset({"mr", "mrs", "ms", "mx", "miss", "sir", "madam", "dr"})
_ROLE_TITLES = _TITLES - _ADDRESS_TITLES
_PRONOUNS = english.words("object_pronouns")
_IT = frozenset({"it", "them"})  # the thing handed over, said again
_FILLERS = english.words("courtesy") | frozenset(
    {"to", "for", "it", "its", "is", "the", "one", "please", "oh", "sorry", "i", "mean", "meant"}
)
_AND = frozenset({"and", "or", "plus"})
_ARTICLES = frozenset({"the", "our", "a", "an"})
_SENTENCE_END = re.compile(r"[.!?;\n]")
_PAUSE = re.compile(r"[,:]")


@dataclass(frozen=True)
class _Word:
    text: str  # as written, without a possessive 's
    folded: str
    possessive: bool
    opens: bool  # the first word of a sentence
    after_pause: bool = False  # a comma (or colon) before it, as the reader's ``Token``

    @property
    def word(self) -> str:
        """The folded word, as the reader's ``Token`` names it (``name_reading.slot_at``)."""
        return self.folded


def _tokens(text: str) -> list[_Word]:
    """The words of a text as the reader's tokenizer splits them (any script, inner
    apostrophes kept, a possessive 's marked), each with whether it opens a sentence."""
    flat = text.replace("’", "'")
    found = list(language.WORD.finditer(flat))
    out = []
    for n, m in enumerate(found):
        raw = m.group(0)
        possessive = raw.lower().endswith("'s")
        bare = raw[:-2] if possessive else raw
        gap = flat[found[n - 1].end() : m.start()] if n else ""
        opens = n == 0 or bool(_SENTENCE_END.search(gap))
        pause = bool(_PAUSE.search(gap))
        out.append(_Word(bare, language.fold(bare), possessive, opens, pause))
    return out


@dataclass(frozen=True)
class _Mention:
    people: frozenset[str]  # whom the words may mean: one, or each sharing a name word
    start: int
    end: int  # exclusive
    possessive: bool


def _names(office: Office) -> list[tuple[tuple[str, ...], frozenset[str]]]:
    """Every way a person is written, as folded word tuples, longest first, with whom each
    may mean. A spelling the office declares for someone (full name, alias, id) means only
    them; a part of a name ("Page" of "Oksana Page") means everyone it is a part of, unless
    it is declared for someone ("Page", Page Holloway's alias)."""
    declared: dict[tuple[str, ...], set[str]] = {}
    parts: dict[tuple[str, ...], set[str]] = {}

    def key(spelling: str) -> tuple[str, ...]:
        # split as the text is (``_tokens``), so "Ms D'Amato" is the same words in both
        return tuple(w.folded for w in _tokens(spelling))

    for p in office.people:
        for s in {p.name, *p.aliases, p.id, p.id.replace("_", " ")}:
            if k := key(s):
                declared.setdefault(k, set()).add(p.id)
        for w in name_parts.calling_words(p):  # never a middle "van", "bin", "Thị" alone
            if len(w) > 1 and (k := key(w)):
                parts.setdefault(k, set()).add(p.id)
        for s in name_parts.surname_phrases(p):  # "de la Cruz", "van Dijk"
            if len(k := key(s)) > 1:
                parts.setdefault(k, set()).add(p.id)
        for alias in p.aliases:  # "Manager Mao": "the manager" names them too
            alias_words = re.findall(r"\w+", language.fold(alias))
            for w in alias_words:
                if w in _ROLE_TITLES:
                    parts.setdefault((w,), set()).add(p.id)
            if len(alias_words) > 1 and alias_words[0] in _ADDRESS_TITLES:
                # "Mrs Okafor": the surname alone names her too, as the reader reads it
                for w in alias_words[1:]:
                    if len(w) > 1 and (k := key(w)):
                        parts.setdefault(k, set()).add(p.id)
    for rank, holder in rank_titles(office).items():  # "the Station Officer": the one
        declared.setdefault(tuple(rank.split()), set()).update(holder)
    found = {k: frozenset(ids) for k, ids in parts.items()}
    found.update({k: frozenset(ids) for k, ids in declared.items()})
    return sorted(found.items(), key=lambda x: -len(x[0]))


def _item_words(office: Office) -> frozenset[str]:
    """The one-word names of the office's items, singular and plural ("puppet", "puppets")."""
    found = set()
    for t in office.item_types:
        for name in (t.name, *t.synonyms, t.id.replace("_", " ")):
            key = language.fold(name)
            if key and " " not in key:
                found |= {key, language.plural(key)}
    return frozenset(found)


def _item_heads(office: Office) -> frozenset[str]:
    """The last word of each name of the office's items, singular and plural."""
    found = set()
    for t in office.item_types:
        for name in (t.name, *t.synonyms):
            key = language.fold(name).split()
            if key:
                found |= {key[-1], language.plural(key[-1])}
    return frozenset(found)


def _name_words(office: Office) -> frozenset[str]:
    return frozenset(language.fold(w) for p in office.people for w in name_parts.calling_words(p))


def _written_as_name(
    words: list[_Word], n: int, items: frozenset[str], name_words: frozenset[str]
) -> bool:
    """Whether a one-word name that is also an English word ("penny", "Ivy's", "Mark") is
    meant as the person where it stands: the reader's own decision
    (``core.name_reading.read_name``), so that the guard and the reader agree on who is
    named in any casing. A reading the reader would ask about counts: the requester's answer
    settles it for the reader, and the name's role is still checked here."""
    slot = slot_at(words, n, items=items, name_words=name_words)
    return read_name(slot) != "word"


class _OfficeWords:
    """The office's spellings of people, items and operations the guard reads with: built
    once per office (``_words_of``), not at every check (3.5 ms of every reading of a text,
    several readings per consent check, on the event loop). The names are looked up by their
    first word, longest first, so a text is read in one pass, not once per name."""

    __slots__ = (
        "family",
        "item_heads",
        "items",
        "name_words",
        "names_by_first",
        "operations",
        "ranks",
        "rooms",
        "seated",
        "spellings",
    )

    def __init__(self, office: Office) -> None:
        self.names_by_first: dict[str, list[tuple[tuple[str, ...], frozenset[str]]]] = {}
        for key, people in _names(office):
            self.names_by_first.setdefault(key[0], []).append((key, people))
        self.items = _item_words(office)
        # the last words of every name of a thing ("knife" of "craft knife"): what a
        # colleague is said to have is one of the office's things ("Olive has a craft knife")
        self.item_heads = self.items | _item_heads(office)
        self.name_words = _name_words(office)
        # "to the curator" (of "Curator Moreau"): a one-word rank is a role title, named in
        # lower case too, as the reader reads it
        self.ranks = frozenset(r for r in rank_titles(office) if " " not in r)
        # "the carver on bench 3 needs ...": the colleague of that workstation, named (the
        # reader's ``seated_subject``)
        said = [(t.name, *t.synonyms) for t in office.item_types]
        said += [(f.name, *f.synonyms) for f in office.facilities]
        self.seated = SeatedSubject.of_names(office, (name for names in said for name in names))
        # how each colleague spells their own name: "Sofía" typed with its mark is Sofía
        # Ramírez, not also Sofia Kowalczyk (the reader's ``exact_spelling``)
        self.spellings = own_spellings(office)
        # "Ms Grant": the people whose family name a word is, in the office's name order (the
        # reader's ``surnames.family_names``), for a name said after a title of address
        self.family = {
            k: frozenset(ids)
            for k, ids in family_names(
                office, lambda s: " ".join(w.folded for w in _tokens(s))
            ).items()
        }
        self.operations = _operation_verbs(office)
        # the words of the office's rooms and facilities ("post desk", "lounge")
        self.rooms = frozenset(
            w
            for name in (
                *(loc.name for loc in office.locations),
                *(n for f in office.facilities for n in (f.name, *f.synonyms)),
            )
            for w in language.fold(name).split()
        )


OFFICES_KEPT = 16  # offices whose words are kept (a service serves a few)
TEXTS_KEPT = 2048  # readings kept, by (office, text, requester)

# By the office's identity: an office is frozen, and hashing one (all its people and items)
# costs more than a lookup should. The weak reference tells a live office from a dead one
# whose id was reused.
_WORDS: dict[int, tuple[weakref.ref[Office], _OfficeWords]] = {}


def _words_of(office: Office) -> _OfficeWords:
    kept = _WORDS.get(id(office))
    if kept is not None and kept[0]() is office:
        return kept[1]
    if len(_WORDS) >= OFFICES_KEPT:
        _WORDS.clear()
    words = _OfficeWords(office)
    _WORDS[id(office)] = (weakref.ref(office), words)
    return words


def _mentions(words_of_office: _OfficeWords, words: list[_Word]) -> list[_Mention]:
    names = words_of_office.names_by_first
    items, name_words = words_of_office.items, words_of_office.name_words
    out: list[_Mention] = []
    n = 0
    while n < len(words):
        hit = None
        for key, people in names.get(words[n].folded, ()):
            span = tuple(w.folded for w in words[n : n + len(key)])
            if span != key:
                continue
            # a name that is also a word counts only where it is read as the person ("to
            # penny", "May's desk"; not "in May", "the grace period"); a role title is a role
            word = key[0]
            if len(key) == 1 and n > 0 and words[n - 1].folded in ("a", "an"):
                continue  # "for a min": nobody is "a Min" (the reader's reading too)
            role = word in _ROLE_TITLES or word in words_of_office.ranks
            if len(key) == 1 and not role and is_word_name(word):
                if not _written_as_name(words, n, items, name_words) and not _said_alone_as_fix(
                    words, n
                ):
                    continue
            written = [w.text for w in words[n : n + len(key)]]
            people = spelled_by(words_of_office.spellings, written, people)
            hit = _Mention(people, n, n + len(key), words[n + len(key) - 1].possessive)
            break
        family = words_of_office.family.get(words[n].folded)
        titled = n > 0 and words[n - 1].folded in _ADDRESS_TITLES and family is not None
        if titled and family and (hit is None or hit.end - hit.start == 1):
            # "could Ms Grant sign it?": a title goes with a family name (Nadia Grant, not
            # Grant O'Sullivan, whose given name it is), as the reader reads it
            hit = _Mention(family, n, n + 1, words[n].possessive)
        if hit is None:
            n += 1
            continue
        out.append(hit)
        n = hit.end
    return out


def _said_alone_as_fix(words: list[_Word], n: int) -> bool:
    """ "to sam. sorry not sam, robin": a name word said alone as a correction, at its
    sentence's end, is the person (the reader reads it so, ``screen.correction``): a
    correction replaces what was just said, and a bird is nothing it could replace. So is
    one said as the subject of the correction's need of the thing ("no wait, will needs it"),
    as the reader takes it (``core.needed_instead``)."""
    if n + 1 < len(words) and not words[n + 1].opens:
        if not needs_the_thing(_clause_after(words, n + 1)):
            return False
    at = n - 2 if n >= 2 and words[n - 2].folded == "not" else n  # "not sam, robin"
    said = tuple(w.folded for w in words[:at])
    return any(said[len(said) - len(mark) :] == mark for mark in _CORRECTION_MARKS)


def _before_at(words: list[_Word], at: int) -> int:
    """Where the word before position ``at`` is, skipping titles and articles ("to Dr. Hal",
    "by the manager"); -1 where there is none."""
    k = at - 1
    while k >= 0 and (words[k].folded in _TITLES or words[k].folded in _ARTICLES):
        k -= 1
    return k


def _before(words: list[_Word], at: int) -> str:
    """The word before position ``at``, skipping titles and articles."""
    k = _before_at(words, at)
    return words[k].folded if k >= 0 else ""


def _ahead(words: list[_Word], at: int) -> Ahead:
    """The two words before the word before ``at``, within its sentence and phrase, as the
    reader takes them: "the one" in "the one on Hal's desk" (where the item lies)."""
    return ahead_at(words, _before_at(words, at))


def _is_give(word: str, operations: frozenset[str]) -> bool:
    """ "bring Hal ...", "printed Hal ...": a giving verb or the office's own operation verb."""
    verbs = _GIVE | operations
    return word in verbs or bool(language.verb_lemmas(word) & verbs)


def _operation_verbs(office: Office) -> frozenset[str]:
    return frozenset(
        language.fold(v.split()[0]) for op in office.operations for v in (*op.verbs, op.name) if v
    )


def _receiving(
    words: list[_Word], start: int, end: int, possessive: bool, operations: frozenset[str]
) -> bool:
    """Whether the words at [start, end) (a name or a pronoun) stand in a receiving or doing
    role."""
    before = _before(words, start)
    after = words[end].folded if end < len(words) else ""
    if possessive:  # "on Hal's desk": their place; "Hal's form": an owner
        return names_receiving_place(before, after, _ahead(words, start))
    if before in _TO or before in _BY or _is_give(before, operations):
        return True
    if appositive_preposition(words, start, end) in _TO:
        return True  # "for the cover teacher, Ms Nguyen"
    if before in _DOER_VERBS or language.verb_lemmas(before) & _DOER_VERBS:
        return True
    if asked_to_have(before, [w.folded for w in words[end : end + 3]]):
        return True  # "could Linh have a stapler?", "Linh could do with one"
    if caused_for(before, [w.folded for w in words[end : end + 9]]):
        return True  # "could Linh get my report printed": made for her
    if _picked_out(words, start, end):
        return True  # "it's Linh who needs it"
    nxt = words[end + 1].folded if end + 1 < len(words) else ""
    if before in _MODALS and _does_by_hand([w.folded for w in words[end : end + 4]]):
        return True  # "could Hal sign my form?", "would Hal be able to stamp it?"
    return after == "to" and _is_doing(nxt)


def _is_doing(word: str) -> bool:
    return word in _DOING or bool(language.verb_lemmas(word) & _DOING)


def _does_by_hand(after: list[str]) -> bool:
    """Whether the words after a name asked with a modal are the work done by hand: "sign
    ...", "be able to sign ..."."""
    if after[:3] == ["be", "able", "to"]:
        after = after[3:]
    return bool(after) and _is_doing(after[0])


# What stands after the first object of "sort him one", "find her some", "get them a few":
# a second object that is a thing, so the pronoun is the one it is for
_SECOND_OBJECT = frozenset({"one", "some", "a", "an", "another", "any", "two", "few", "spare"})


def _double_object(words: list[_Word], n: int) -> bool:
    """Whether the pronoun at ``n`` is the first of a verb's two objects ("can you sort him
    one?", "find her one", "get them some"): the one the thing is got for, whatever the
    verb. "find her pen" (her own pen) has no second object, and a verb must come first."""
    if n == 0 or words[n].opens or n + 1 >= len(words) or words[n + 1].opens:
        return False
    if words[n].folded not in _PRONOUNS or words[n + 1].folded not in _SECOND_OBJECT:
        return False
    verb = words[n - 1].folded
    return bool(language.verb_lemmas(verb)) and verb not in _PRONOUNS


_CLEFT_VERBS = frozenset({"need", "want", "use"})


def _picked_out(words: list[_Word], start: int, end: int) -> bool:
    """ "it's Hal who needs it", "it is Hal that wants the copy": a cleft that picks out the
    one the item is for."""
    if start >= 1 and words[start - 1].folded == "it" and words[start - 1].possessive:
        pass  # "it's Hal"
    elif not (
        start >= 2 and words[start - 2].folded == "it" and words[start - 1].folded in {"is", "s"}
    ):
        return False
    if end + 1 >= len(words) or words[end].folded not in {"who", "that"}:
        return False
    verb = words[end + 1].folded
    return verb in _CLEFT_VERBS or bool(language.verb_lemmas(verb) & _CLEFT_VERBS)


# What a requester says before the name they correct a receiver to: "to Siobhán, no wait,
# Łukasz", "for Hal - sorry, I meant Dawn"
_CORRECTION_MARKS = tuple(
    tuple(mark.split())
    for mark in (
        "no wait", "wait no", "oh wait", "no sorry", "sorry no", "i mean", "i meant",
        "sorry", "no", "nope", "oops", "make it", "make that",
    )
)  # fmt: skip


_SUBJECT_AFTER = frozenset({"has", "have", "is", "was", "will", "can", "could", "might", "s"})


def _corrects(words: list[_Word], mentions: list[_Mention], k: int) -> bool:
    """Whether mention ``k`` is the name a correction puts in place of the one said before
    it ("..., no wait, Łukasz", "... sorry, not Siobhán, Łukasz"): it stands where that
    one stood, so after a receiver it receives."""
    at, end = mentions[k].start, mentions[k].end
    after = words[end].folded if end < len(words) else ""
    clause = _clause_after(words, end)
    if (after in _SUBJECT_AFTER or language.is_finite_verb(after)) and not needs_the_thing(clause):
        # "... sorry, Dawn has it": Dawn is the subject of news, no receiver; "..., no wait,
        # Dawn needs it first" names who it goes to instead (the reader's correction)
        return False
    before = mentions[k - 1] if k >= 1 else None
    if before is not None and before.end == at and before.start >= 1:
        if words[before.start - 1].folded == "not":
            at = before.start - 1  # the name refused, then the one meant
    said = tuple(w.folded for w in words[:at])
    return any(said[len(said) - len(mark) :] == mark for mark in _CORRECTION_MARKS if mark)


def _clause_after(words: list[_Word], end: int) -> list[str]:
    """The words from ``end`` to the next pause or sentence end."""
    out: list[str] = []
    for w in words[end:]:
        if out and (w.opens or w.after_pause):
            break
        out.append(w.folded)
    return out


def _in_roles(office: Office, text: str, requester: str) -> frozenset[str]:
    office_words = _words_of(office)

    def is_person(said: str) -> bool:
        return any(m.possessive for m in _mentions(office_words, _tokens(said)))

    # read as the reader reads it: "leave it w/ Hal" is "leave it with Hal", and "put the
    # ruler next to Hal's" is "at Hal's desk" (near_possessive), where Hal receives it; "bring
    # me the ruler at Hal's desk" is Hal's ruler, Hal no receiver (placed_thing)
    read = near_possessives(placed_things(undotted(text), is_person), is_person)
    read = office_words.seated(read)
    return _roles_in(office_words, read, requester)


# A reading depends on the office's words, the text and who wrote it only: remembered, as
# the guard reads the same request (and the same replies) at every hand-over it checks.
@functools.lru_cache(maxsize=TEXTS_KEPT)
def _roles_in(office_words: _OfficeWords, text: str, requester: str) -> frozenset[str]:
    words = _tokens(text)
    mentions = _mentions(office_words, words)
    operations = office_words.operations
    named: set[str] = set()
    refused: set[str] = set()
    last_receiver: frozenset[str] = frozenset()
    receiving_end = -1  # where the last receiving name ended: "to Hal and Dawn" names both
    for k, m in enumerate(mentions):
        joined = receiving_end >= 0 and m.start == receiving_end + 1
        joined = joined and words[receiving_end].folded in _AND
        receiving = _receiving(words, m.start, m.end, m.possessive, operations)
        correcting = receiving_end >= 0 and not m.possessive and _corrects(words, mentions, k)
        if correcting:  # "to Siobhán, no wait, Łukasz": Siobhán is no longer meant
            refused |= last_receiver - m.people
        if receiving or correcting or (joined and not m.possessive):
            named |= m.people
            receiving_end = m.end
            last_receiver = m.people
    named -= refused
    for m in mentions:  # "for Grace's meeting": whose occasion the thing is for
        if _for_an_occasion(words, m, office_words):
            named |= m.people
    if not named and _taken_to_a_room(words, office_words.rooms):
        # "Zhang needs my stapler. take it to the meeting room": nobody is named to receive
        # it, and the one colleague said to need it (or to be in that room) is whom it goes
        # to there (the reader's ``room_receiver``); several such decide nothing
        there = {
            p
            for m in mentions
            if len(m.people) == 1
            and (_said_to_need(words, m) or _said_in_a_room(words, m, office_words.rooms))
            for p in m.people
        } - {requester}
        if len(there) == 1:
            named |= there
    folded = [w.folded for w in words]
    if not named and (
        _one_handed(words, operations) or taken_across(folded, lambda w: _is_give(w, operations))
    ):
        # "Sue (on reception) needs a highlighter, can you take one down": nobody named in a
        # receiving place, and "one" handed over is the thing the one colleague said to need
        # it needs; several such decide nothing. So is "it" taken over ("Mark needs my
        # ruler, can you take it over"): to the one said to need it, whoever else is named
        needing = {
            p
            for m in mentions
            if len(m.people) == 1
            and not m.possessive
            and _said_to_need(words, m, office_words.rooms)
            for p in m.people
        } - {requester}
        if len(needing) == 1:
            named |= needing
    if not named and handed_on(folded, lambda w: _is_give(w, operations)):
        # "wang wants my report, can u send it over": the one colleague said to want the
        # requester's own thing is whom "it" goes to (``wanted_own``); where another is said
        # to want or need anything too ("and Will needs it too"), nobody is picked
        wishing = {
            p
            for m in mentions
            if wishes_said(folded, m.end, folded_is=m.possessive)
            or (not m.possessive and _said_to_need(words, m))
            for p in m.people
        } - {requester}
        wanting = {
            p
            for m in mentions
            if len(m.people) == 1 and wants_own_thing(folded, m.end, folded_is=m.possessive)
            for p in m.people
        } - {requester}
        if len(wanting) == 1 and wishing == wanting:
            named |= wanting
    for n, w in enumerate(words):
        after = words[n + 1].folded if n + 1 < len(words) else ""
        at_place = pronoun_receiving_place(  # "at her desk", not "the one on her desk"
            _before(words, n), w.folded, after, _ahead(words, n)
        )
        # "Will's calculator died, can he have mine?": "he" asked to have it receives it
        asked = subject_asked_to_have(_before(words, n), w.folded, folded[n + 1 : n + 10])
        if (
            not at_place
            and not asked
            and (
                w.folded not in _PRONOUNS
                or not (_receiving(words, n, n + 1, False, operations) or _double_object(words, n))
            )
        ):
            continue
        # the one person named who is not the owner of what is handed over (named after
        # the pronoun: "take him May's ice pack") nor a source ("from May"); "Hal's clipboard
        # snapped, lend him mine" is about Hal
        candidates = {
            person
            for m in mentions
            if not (m.possessive and m.start > n)
            and _before(words, m.start) != "from"
            and not _holder(words, m.end, office_words.item_heads)
            and not _owner_carried(folded, m, n, office_words.items)
            for person in m.people
        } - {requester}
        if len(candidates) > 1 and any(x.folded in _IT for x in words[max(0, n - 3) : n]):
            # "Nadia needs Miles's dev kit, take it to her": the owner of the thing "it" is
            # no receiver of it either, where one other person is named ("Hal's clipboard
            # snapped, Dawn says: lend him mine" admits no one)
            candidates = {
                person
                for m in mentions
                if not m.possessive and _before(words, m.start) != "from"
                for person in m.people
            } - {requester}
        if len(candidates) > 1:
            # "Kit's after a torch, take Omar's over to him": of several named, the one
            # said to need a thing is whom it goes to (the owner and the one who said so
            # are not), where exactly one is
            needing = {p for m in mentions if _said_to_need(words, m) for p in m.people}
            if len(needing & candidates) == 1:
                candidates &= needing
        if len(candidates) == 1:
            named |= candidates
    return frozenset(named - {requester})


def _owner_carried(folded: list[str], m: _Mention, n: int, items: frozenset[str]) -> bool:
    """Whether ``m`` is the possessive of the thing carried to the pronoun at ``n`` ("take
    May's over to her", "bring Chen's scissors to him"): its owner, never whom "her" means
    (``core.handed_owner``; "May's back to her" goes home to May)."""
    if not m.possessive:
        return False
    to = carried_to(folded, m.end, items)
    return to is not None and to + 1 == n


def _for_an_occasion(words: list[_Word], m: _Mention, office_words: _OfficeWords) -> bool:
    """ "bring some tape to the post desk for Grace's meeting": a possessive after "for"
    before a word that names an occasion of theirs (``core.occasion_noun``), not a thing of
    the office ("for Grace's ruler" is hers, whoever gets it), in words that take the thing
    to a room: the one it is for."""
    if not m.possessive or m.end >= len(words) or _before(words, m.start) != "for":
        return False
    nxt = words[m.end].folded
    if nxt in office_words.items or words[m.end].opens or words[m.end].after_pause:
        return False
    return occasion_noun(nxt) and _taken_to_a_room(words, office_words.rooms)


def _taken_to_a_room(words: list[_Word], rooms: frozenset[str]) -> bool:
    """Whether the words take a thing "to"/"into" a room of the office ("to the post desk"),
    as the reader's ``occasion.taken_to_a_room``: without one, an occasion says only why."""
    return any(
        w.folded in ("to", "into")
        and any(x.folded in rooms for x in words[n + 1 : n + 4] if x.folded not in _ARTICLES)
        for n, w in enumerate(words)
    )


# "needs", "is after", "could do with" (``need_phrases``): said right after a name; after a
# possessive's "'s" (the "is" of "Kit's after a torch") without that "is"
_NEEDS = (("needs",), ("need",), *(tuple(p.split()) for p in english.entries("need_phrases")))


def _said_to_need(words: list[_Word], m: _Mention, rooms: frozenset[str] = frozenset()) -> bool:
    """Whether the name ``m`` is the subject of a need: "Kit needs a torch", "Kit's after a
    torch", "Kit is looking for one", "Kit on reception needs one" (where Kit is, from
    ``rooms``, the words of the office's places, comes between)."""
    at = m.end
    if not m.possessive and at < len(words) and words[at].folded in _PLACING:
        k = at + 1
        while k < len(words) and words[k].folded in _ARTICLES:
            k += 1
        if k < len(words) and words[k].folded in rooms:
            while k < len(words) and words[k].folded in rooms:
                k += 1
            at = k
    after = tuple(w.folded for w in words[at : at + 4])
    if not m.possessive and wants_to_have([w.folded for w in words[at : at + REACH]]):
        return True  # "Kit wants to borrow my torch": a want of having it (the reader's too)
    for phrase in _NEEDS:
        said = phrase[1:] if m.possessive and phrase[0] in ("s", "is") else phrase
        if m.possessive and said == phrase:
            continue  # "Kit's needs": no "is" in "'s" here
        if said and after[: len(said)] == said:
            return True
    return False


_BE = frozenset({"is", "was"})
# where a person is, said after their name ("Sue on reception", "Wang at the print room")
_PLACING = frozenset({"on", "at", "in", "by", "near"})
_STAND_INS = frozenset({"one", "some"})


def _one_handed(words: list[_Word], operations: frozenset[str]) -> bool:
    """Whether a giving verb takes "one" or "some" right after it ("take one down", "grab
    some"): the thing said before, handed to nobody named in the same breath."""
    return any(
        _is_give(w.folded, operations) and words[n + 1].folded in _STAND_INS
        for n, w in enumerate(words[:-1])
    )


_IN = frozenset({"in", "at", "inside"})


def _said_in_a_room(words: list[_Word], m: _Mention, rooms: frozenset[str]) -> bool:
    """Whether the name ``m`` is said to be in a room of the office: "Zhang is in the
    meeting room", "Zhang's at the lounge" (the reader's ``room_receiver``)."""
    at = m.end
    if not m.possessive:
        if at >= len(words) or words[at].folded not in _BE:
            return False
        at += 1
    if at >= len(words) or words[at].folded not in _IN:
        return False
    at += 1
    while at < len(words) and words[at].folded in _ARTICLES:
        at += 1
    return at < len(words) and words[at].folded in rooms


_HAS = frozenset({"has", "have", "had"})


# "has no", "has none", "has not got": a lack, not a having
_NONE = frozenset({"no", "none", "nothing", "not", "nt"})
# "has got", "has gotten": a having said with "got", no perfect of another verb
_GOT = frozenset({"got", "gotten"})


def _holder(words: list[_Word], end: int, things: frozenset[str]) -> bool:
    """Whether the name ending at ``end`` is said to have something ("Rhys has a spare one,
    bring it to her"): the one it comes from, never the "her" it goes to. One said to have
    none ("Zoë has no headset, take her mine") lacks it: whom it goes to; one who "has been"
    somewhere holds nothing by that, nor one who has what is no thing of the office ("Wang
    has a meeting soon, take her my stapler", "Jae-won has a flat Polo in lane B, take him
    the jump pack": what they are busy with; ``things``: the words that end the office's
    names of things)."""
    if end >= len(words) or words[end].folded not in _HAS:
        return False
    after = words[end + 1].folded if end + 1 < len(words) else ""
    # "Grace has been out on site all day, take her a ruler": "has been" is the perfect of
    # "be", a state she was in, no having; so is any perfect ("Mei has hurt her ankle, take
    # her an ice pack": what happened to her), but "has got" is a having
    perfect = after not in _GOT and language.is_past_participle(after)
    if after in _NONE or after == "been" or perfect:
        return False
    had: list[str] = []
    for w in words[end + 1 : end + 1 + _HAD_SPAN]:
        if w.after_pause and had:
            break
        had.append(w.folded)
    return bool(set(had) & (things | _HAD_STAND_INS))


# How far after "has" what is had is looked for, and the words that stand for a thing had
# ("Rhys has a spare one", "Ann has some", "Hal has it")
_HAD_SPAN = 5
_HAD_STAND_INS = frozenset({"one", "ones", "some", "it", "them", "spare", "spares", "any"})


def _just_a_name(office: Office, text: str) -> frozenset[str]:
    """The people a reply names when it says nothing but names ("Hal Brooks.", "to Hal")."""
    return _only_names_in(_words_of(office), text)


@functools.lru_cache(maxsize=TEXTS_KEPT)
def _only_names_in(office_words: _OfficeWords, text: str) -> frozenset[str]:
    words = _tokens(text)
    mentions = _mentions(office_words, words)
    covered = {n for m in mentions for n in range(m.start, m.end)}
    rest = [w for n, w in enumerate(words) if n not in covered and w.folded not in _FILLERS]
    return (
        frozenset(p for m in mentions for p in m.people) if mentions and not rest else frozenset()
    )


@functools.lru_cache(maxsize=TEXTS_KEPT)
def _people_in(office_words: _OfficeWords, text: str) -> frozenset[str]:
    """Everyone a name in ``text`` may mean."""
    return frozenset(p for m in _mentions(office_words, _tokens(text)) for p in m.people)


def named_recipients(office: Office, stm: ShortTermMemory) -> set[str]:
    """The people the requester named as a recipient or a doer, in the instruction, in their
    later messages in their own chat, or by a yes to the assistant's offer there."""
    own = ChatRef(kind="dm", id=stm.requester)
    found = set(_in_roles(office, stm.text, stm.requester))
    last_offer: str | None = None
    for turn in stm.dialogue:
        if turn.chat != own:
            continue
        if turn.direction == "out" and turn.question_id:
            last_offer = turn.text
            continue
        if turn.direction != "in" or turn.person != stm.requester:
            continue
        found |= _in_roles(office, turn.text, stm.requester)
        found |= _just_a_name(office, turn.text) - {stm.requester}
        if last_offer is not None and stance(turn.text) == "yes":
            found |= _in_roles(office, last_offer, stm.requester)
    return found


def _frame(office: Office, stm: ShortTermMemory) -> TaskFrame:
    # The reader (and lemminflect's tables under it) is imported on the first check that
    # needs it, not with the runtime: a third of a service's start otherwise. Its parser is
    # the reasoner's, built by the service's warm-up thread, and remembers what it read.
    from assistantx.agents.symbolic.reading.parser import shared_parser

    answers = list(stm.requester_answers())
    return shared_parser(office).parse_with_answers(stm.text, stm.requester, answers)


def _frame_if_confirmed(office: Office, stm: ShortTermMemory) -> TaskFrame:
    """The reader's frame of the request as if the requester had said yes to its question
    (a "Shall I ...?"); a question that is no such offer leaves no tasks."""
    from assistantx.agents.symbolic.reading.parser import shared_parser

    answers = [*stm.requester_answers(), "yes"]
    return shared_parser(office).parse_with_answers(stm.text, stm.requester, answers)


def _written_by_requester(office: Office, stm: ShortTermMemory) -> set[str]:
    """Everyone a name in the requester's own words may mean (the instruction and their
    messages in their own chat)."""
    own = ChatRef(kind="dm", id=stm.requester)
    texts = [stm.text] + [
        t.text
        for t in stm.dialogue
        if t.chat == own and t.direction == "in" and t.person == stm.requester
    ]
    office_words = _words_of(office)
    return {p for text in texts for p in _people_in(office_words, text)}


def named_doers(office: Office, stm: ShortTermMemory) -> set[str]:
    """Who does the work by hand (signs, seals): the doers the requester named in a receiving
    or doing place (``named_recipients``) and the doers of the reader's frame of the request
    whom the requester's own words name."""
    frame = _frame(office, stm)
    if not frame.tasks and frame.question is not None:
        # The reader asked "Shall I get your form signed by Hal ...?" and no answer came (an
        # LLM reasoner or the optimal policy need not ask): the doer of the reading it asked
        # about is still the one the requester's words name in that role. Only doers come
        # from it, and the work puts the item back in the locker.
        frame = _frame_if_confirmed(office, stm)
    doers = {t.actor for t in frame.tasks if t.actor and t.actor != stm.requester}
    if doers:
        doers &= _written_by_requester(office, stm)
    return named_recipients(office, stm) | doers


def named_receivers(office: Office, stm: ShortTermMemory) -> set[str]:
    """Who may collect a hand-over: the recipients the requester named (``named_recipients``)
    and the recipient of each thing the reader's frame of the request has made at the
    requester's own request (``made_for``), whom the requester's own words name."""
    return named_recipients(office, stm) | made_for(office, stm)


def made_for(office: Office, stm: ShortTermMemory) -> set[str]:
    """The recipients of what the reader's frame makes for the requester out of their own
    thing or out of nothing (a copy of my file, a printout of my document, a coffee), where
    the requester's own words name them: "Zhang needs a copy of my file", "Lin wants a
    printout of my document". The reading the symbolic reasoner plans with is the reading
    the guard lets collect, so "X needs" needs no second list of phrases here. Only made
    things count: nobody owns them but the one it is made for (no owner's yes is due,
    consent rule 3), and what it is made of is the requester's to give; a belonging of
    anyone's, even the requester's own, still goes only to one named in a receiving place
    (a frame that misreads "May wants it on the board, my clipboard is for Rich" cannot make
    May a party)."""
    frame = _frame(office, stm)
    made = {
        t.recipient
        for t in frame.tasks
        if t.recipient and t.owner in (None, stm.requester) and _makes_a_thing(office, t)
    }
    made.discard(stm.requester)
    return made & _written_by_requester(office, stm) if made else set()


def _makes_a_thing(office: Office, task: Task) -> bool:
    """Whether the task's operation makes a new thing (a copy, a printout, a coffee), which
    is what its recipient collects; one that gives its input back changed (a heat) does not."""
    op = operation_of(office, task)
    return op is not None and any(o.id == op and o.product for o in office.operations)
