"""Where a service that sends an item outside the office sends it ("fax my form to the county
tax office", "send out my drawing to the client"), found once, on the tokens, by the readings
stage, and handed forward: the readings stage reads the verb phrase as the service's task word
and the words after its "to" as a place outside (never a colleague to look up); the parser
takes the phrase as the task's destination.

The destination is outside the office, so it is kept in the requester's own words (a number,
an organisation) for the outcome the requester reads.
"""

from __future__ import annotations

import re
from collections.abc import Collection, Iterable, Mapping, Sequence
from dataclasses import dataclass

from assistantx.agents.symbolic.reading.address_run import address_run
from assistantx.agents.symbolic.reading.destination_detail import detail_after
from assistantx.agents.symbolic.reading.named_place import named_place
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language

# What ends a destination: a sentence or clause end, or a courtesy word after it.
_END_MARKS = frozenset(".!?;,\n")
_END_WORDS = frozenset(
    {"please", "pls", "thanks", "thank", "thx", "asap", "today", "tonight", "tomorrow", "now"}
)
_TAIL_WORDS = 3  # the town (and postcode) after an address's comma
# a street line after an address's comma ("Unit 4 Dockside Road", "Flat 2, 14 Elm Road"): a
# number among capitalised words, so a part of it may be longer than a town's
_STREET_WORDS = 6
_DIALLED_DIGITS = 6  # the fewest digits of a phone or fax number said after a comma
_LONGEST = 80  # a destination longer than this is not one phrase: ask instead
# The object pronouns of a request whose item (and destination) a statement before it named.
_PRONOUNS = frozenset({"it", "them", "this", "that"})
# Subjects that make a statement of going a person's own ("I'm going to the bank").
_PERSONS = frozenset({"i", "im", "we", "you", "he", "she", "they", "me", "us", "him", "her"})
# Words of going or sending before a statement's destination ("needs to go out *to* ...").
# ("go *back* to the supplier": the thing goes there all the same)
_GOING = frozenset({"go", "goes", "going", "gone", "out", "off", "away", "over", "back"})
# The words that name a service as the means of sending ("send it to the council *by* courier",
# "go out to the plant *with the* courier", "off to the lab *on the* tube"), an article or "our"
# between them and the service.
_MEANS = frozenset({"by", "via", "with", "on"})
_MEANS_ARTICLES = frozenset({"the", "a", "our", "your"})
# A join that opens the request's next clause of handing or telling ("to the client *and let*
# me know", "*and then bring* me the camera"), not a firm's name ("Smith and Sons"); a verb of
# other work ("and vet it") stays unread, so the part is asked about, never reordered.
_HANDING = english.words("handing_verbs") | english.words("dative_verbs") | {"let", "tell"}
# The words that open a clause of its own after the destination ("to Acme Ltd, Leeds *so that*
# they have it today", "to the clinic *because* ..."): a reason, a consequence or purpose, a
# condition; the destination ends before them.
_CLAUSE_OPENERS = (
    english.words("reason_conjunctions")
    | english.words("consequence_joins")
    | {p for p in english.entries("purpose_openers") if " " not in p}
    | {p for p in english.entries("condition_openers") if " " not in p}
)
# "for me", "for us": whom the request is for, said after the place.
_FOR_WHOM = [["me"], ["us"]]
# The words that are never part of a place's name after its comma ("..., it has to go today",
# "..., print me a tag"): pronouns, said for a clause of its own.
_NOT_PLACE = (
    english.words("pronouns")
    | english.words("object_pronouns")
    | english.words("subject_pronouns")
    | english.words("other_possessives")
    | english.words("clause_breaks")
    | {"me", "us", "my", "your", "our"}
)


# The verbs that open a send-out's purpose infinitive before the work's participle ("to *be*
# laundered", "to *get* resoled"): the work done there, never the place it goes.
_WORK_AFTER = [["be"], ["get"]]


@dataclass(frozen=True)
class VerbPhrase:
    """How a send-out service is asked for: its first word in any form, then the rest as
    written ("send" + "out"); the phrase counts whole, never its first word alone."""

    operation: str
    forms: frozenset[str]
    rest: tuple[str, ...]
    # the words the service's name says before its means ("send by *interlibrary* courier"):
    # said between the article and the means ("with the interlibrary courier"), still the means
    modifiers: frozenset[str] = frozenset()


@dataclass(frozen=True)
class Outside:
    """A send-out service's verb phrase in a request, and where it sends the item."""

    operation: str
    verb_start: int  # token span of the verb phrase
    verb_end: int
    start: int | None  # token span of the destination (after "to"); None: none named
    end: int | None
    phrase: str | None  # the destination in the requester's words
    means: bool = False  # the service named as the means of sending ("by courier")
    # the end of a clause after the place that says how to reach it ("..., their number is
    # 01632 960 123"); its words are the destination's too, never a person or an item
    detail_end: int | None = None

    def holds(self, token: int) -> bool:
        """Whether token index ``token`` is part of the destination."""
        if self.start is None or self.end is None:
            return False
        return self.start <= token < max(self.end, self.detail_end or 0)


def means_words(name: str) -> tuple[str, ...]:
    """The means a send-out service's name says it sends by ("send by courier": "courier";
    "dispatch via fax": "fax"; "send by interlibrary courier": "courier", the head noun that
    ends the name after its "by" or "via"), which also asks for the service as a verb in any
    form ("have it couriered", "needs couriering to Leeds") or as the means said anywhere in
    the request ("send it to Leeds by courier")."""
    return tuple(words[-1:]) if (words := _after_means_word(name)) else ()


def means_modifiers(name: str) -> frozenset[str]:
    """The words a send-out service's name says between its "by" and its means ("send by
    *interlibrary* courier"): a requester may say them before the means too."""
    return frozenset(_after_means_word(name)[:-1])


def _after_means_word(name: str) -> list[str]:
    """The words of a service's name after its last "by" or "via", when that ends it in at
    most a few words (a means, not a clause: "send by courier", "send by interlibrary
    courier"); none otherwise."""
    words = language.fold(name).split()
    at = max((k for k, w in enumerate(words) if w in _MEANS_NAMED), default=None)
    if at is None or not 1 <= len(words) - at - 1 <= _MEANS_NAME_WORDS:
        return []
    return words[at + 1 :]


# The most words a service's name says for its means after "by" ("by interlibrary courier").
_MEANS_NAME_WORDS = 3


# The words of a service's name before the means it sends by ("send *by* courier").
_MEANS_NAMED = frozenset({"by", "via"})


def verb_phrases(
    operation: str, phrases: Iterable[str], modifiers: frozenset[str] = frozenset()
) -> tuple[VerbPhrase, ...]:
    """The verb phrases of one send-out operation ("fax"; "courier", "send out");
    ``modifiers``: the words its name says before its means (``means_modifiers``)."""
    out: list[VerbPhrase] = []
    for phrase in phrases:
        words = language.fold(phrase).split()
        if words:
            forms = frozenset(language.verb_forms(words[0])) | {words[0]}
            out.append(VerbPhrase(operation, forms, tuple(words[1:]), modifiers))
    return tuple(out)


def find_outside(
    tokens: Sequence[Token],
    gaps: Sequence[str],
    phrases: Sequence[VerbPhrase],
    names: Collection[int] = (),
    details: Mapping[str, frozenset[str]] | None = None,
    not_verbs: Collection[int] = (),
) -> Outside | None:
    """The first send-out verb phrase of ``tokens`` (``gaps``: the punctuation before each
    token), with the phrase after the first "to" in the verb's own clause, if any. ``names``:
    token indices inside a name of the office ("the *post* room"), never the verb.
    ``details``: by operation, the words that name a way of reaching its place ("number",
    "postcode"), read in a clause after the place (reading/destination_detail.py).
    ``not_verbs``: token indices inside a proper name of a place outside ("the Leeds
    *Courier* Depot"), never the verb either."""
    words = [t.word for t in tokens]
    no_verb = {*names, *not_verbs} if not_verbs else names
    found = next(
        (
            (k, k + 1 + len(p.rest), p.operation, p.modifiers, k + 1 + len(p.rest))
            for k, word in enumerate(words)
            for p in phrases
            if word in p.forms
            and k not in no_verb
            and tuple(words[k + 1 : k + 1 + len(p.rest)]) == p.rest
        ),
        None,
    ) or _split_particle(words, gaps, phrases, no_verb)
    if found is None:
        return None
    # "send my contract *out* ...": the particle said after the object; its place is read
    # after the particle (``said_to``), the object between stays the object
    verb_start, verb_end, operation, modifiers, said_to = found
    to = None
    for k in range(said_to, len(tokens)):
        if _ends(gaps[k]):
            break  # "please fax my form, it has to go today": another clause's "to"
        if words[k] == "to":
            to = k
            break
    means = _means_before(words, verb_start, modifiers)
    if to is None and means is None:
        to = _at_a_name(tokens, gaps, verb_end, names)  # "archive it at Ironbridge Store"
    if to is None and means is not None:
        to = _to_before(words, gaps, means)  # "send my agreement to the council by courier"
    stop = len(tokens)
    if to is None and means is None and _pronoun_object(words, verb_end):
        to = _stated_before(words, gaps, verb_start)  # "... needs to go out to X, can you fax it"
        stop = verb_start  # the destination stops where the request's clause begins
    start = end = None
    phrase = None
    detail_end = None
    if to is not None and to + 1 < len(tokens):
        start = end = to + 1
        if means is not None and means > to:
            stop = means
        which: str | None = None
        unclear = False
        while end < stop:
            if end > start and _ends(gaps[end]):
                one = _which_one(tokens, gaps, start, end, stop)
                if one is not None:  # "the lab, the Bristol one": the Bristol lab
                    end, which = one
                    unclear = which is None
                    break
                run = address_run(tokens, gaps, end, stop, names)
                if run is not None:  # "..., Civic Centre, Water Gardens, Harlow": all of it
                    end = run
                    break
                more = _address_tail(tokens, gaps, start, end, stop, names)
                if more == end:
                    break
                end = more
                continue
            if words[end] in _END_WORDS or _next_clause(words, end):
                break
            if end > start and words[end] in _CLAUSE_OPENERS:
                break  # "to Acme Ltd so that they have it today": a clause of its own
            if end > start and words[end] == "for" and words[end + 1 : end + 2] in _FOR_WHOM:
                break  # "to Crown Court for me": whom the request is for, not the place
            if end > start and words[end] == "to" and words[end + 1 : end + 2] in _WORK_AFTER:
                break  # "to Parkside Laundry to be laundered" / "to get resoled": the work
            end += 1
        # "to the customer please, Mrs Patel at 14 Elm Road": the address said after it is
        # the place; the destination spans both, so neither is read as someone to find
        named = _address_after(tokens, gaps, end, stop) if which is None else None
        first = start if named is None else named[0]
        end = end if named is None else named[1]
        lead = gaps[first].strip() if named is None else ""  # "+44 ...", "#3 ...": a sign
        said = "".join(
            (gaps[k] if k > first else lead) + tokens[k].text for k in range(first, end)
        ).strip()
        said = which or _bracketed(said.strip("\"'"))
        phrase = said if said and len(said) <= _LONGEST and not unclear else None
        if phrase is not None and set(words[start:end]) <= _PRONOUNS | _PERSONS:
            phrase = None  # "courier it to them": no place said; asked where
        if [words[start]] in _WORK_AFTER:
            # "sent off to be dry cleaned", "send my shoes off to get resoled": the work asked
            # (its purpose infinitive), no place said
            phrase = None
        if phrase is None:
            start = end = None
        else:
            naming = (details or {}).get(operation, english.words("destination_details"))
            detail = detail_after(tokens, gaps, end, stop, naming)
            if detail is not None:  # "..., their number is 01632 960 123": the operator's too
                phrase, detail_end = f"{phrase}, {detail.said}", detail.end
    return Outside(
        operation, verb_start, verb_end, start, end, phrase, means is not None, detail_end
    )


# The most words of the object said between a send-out's verb and its particle ("send *my
# signed delivery note* out").
_SPLIT_OBJECT = 4
_VERB_PARTICLES = english.words("verb_particles")


def _split_particle(
    words: Sequence[str],
    gaps: Sequence[str],
    phrases: Sequence[VerbPhrase],
    names: Collection[int],
) -> tuple[int, int, str, frozenset[str], int] | None:
    """A send-out verb phrase of a verb and one particle ("send out") said with its object
    between them ("send my delivery note out"), in one clause and with no "to" between: the
    verb alone as the phrase's words (``verb_start``, ``verb_end``), the object left to be
    read as the object, and where the words after the particle start."""
    for k, word in enumerate(words):
        if k in names:
            continue
        for p in phrases:
            if word not in p.forms or len(p.rest) != 1 or p.rest[0] not in _VERB_PARTICLES:
                continue
            for j in range(k + 2, min(len(words), k + 2 + _SPLIT_OBJECT)):
                if _ends(gaps[j]) or words[j] in ("to", "and", "then"):
                    break
                if words[j] == p.rest[0]:
                    return k, k + 1, p.operation, p.modifiers, j + 1
    return None


def _at_a_name(
    tokens: Sequence[Token], gaps: Sequence[str], verb_end: int, names: Collection[int]
) -> int | None:
    """The "at" of the verb's clause before a proper name that names nothing of the office
    ("archive my papers *at* Ironbridge Records Store", "... for hallmarking *at* the
    Birmingham Assay Office"): where the service sends the item, said as the place it ends
    up; "at" before anything else (a time, a desk) is none. After "the", the name is two
    capitalised words or more ("the Leeds Depot"), never one ("at the Front")."""
    for k in range(verb_end, len(tokens) - 1):
        if _ends(gaps[k]) or tokens[k].word == "to":
            return None
        if tokens[k].word != "at":
            continue
        name = k + 1
        if tokens[name].word == "the" and tokens[name].text[:1].islower():
            name += 1
            if not _capitalised_run(tokens, gaps, name, names, 2):
                continue
        if (
            name < len(tokens)
            and tokens[name].text[:1].isupper()
            and name not in names
            and not _ends(gaps[name])
            and not language.is_weekday(tokens[name].word)
        ):
            return k
    return None


def _capitalised_run(
    tokens: Sequence[Token], gaps: Sequence[str], start: int, names: Collection[int], least: int
) -> bool:
    """Whether ``least`` capitalised words, none in a name of the office, start at ``start``
    in one clause."""
    said = range(start, start + least)
    return said[-1] < len(tokens) and all(
        tokens[n].text[:1].isupper() and n not in names and not _ends(gaps[n]) for n in said
    )


def _means_before(
    words: Sequence[str], verb_start: int, modifiers: frozenset[str] = frozenset()
) -> int | None:
    """The index of the word that names the service as the means ("by courier", "with the
    courier", "with the interlibrary courier" where ``modifiers``, the words of the service's
    name before its means, hold "interlibrary"), or None."""
    k = verb_start - 1
    while k >= 1 and words[k] in modifiers:
        k -= 1
    if k >= 1 and words[k] in _MEANS_ARTICLES:
        k -= 1
    return k if k >= 0 and words[k] in _MEANS else None


def _address_tail(
    tokens: Sequence[Token],
    gaps: Sequence[str],
    start: int,
    end: int,
    stop: int,
    names: Collection[int] = (),
) -> int:
    """Where a destination that is an address goes on past the comma at ``end`` ("Mrs
    Abernethy at 14 Rosebery Crescent, Edinburgh"; "Broadcast House, Portland Place"): only
    after a comma, only when the words so far look like an address (a house number, a person
    "at" a place) or are a place's proper name ("Broadcast House", "the BBC"), and only over a
    short part that is all names, codes or nouns up to the clause's end ("Edinburgh", "Leeds
    LS1 4DY", "Ward 4", "pharmacy", "main reception"), never a colleague's name nor a day; a
    clause of its own after the comma ("it has to go today", "then print me a tag") or in the
    part ("Leeds so that they have it today": only "Leeds") ends the destination. ``end`` back
    when the destination stops here."""
    if gaps[end].strip() != ",":
        return end
    so_far = tokens[start:end]
    if (
        not any(any(c.isdigit() for c in t.text) for t in so_far)
        and not any(t.word == "at" for t in so_far[1:])
        and not _proper_name(so_far)
        and not named_place(so_far)  # "Eastgate campus, Room 12"
        and not _role_named(tokens, gaps, start, end)
        and not _street_line(tokens[end : end + 2])
        and not _numbers_only(tokens, gaps, end, stop)
    ):
        return end
    words = [t.word for t in tokens]
    k = end
    while (
        k < stop
        and (k == end or not _ends(gaps[k]))
        and words[k] not in _END_WORDS
        and words[k] not in _CLAUSE_OPENERS
        and not _next_clause(words, k)
    ):
        k += 1
    part = tokens[end:k]
    # "Dublin, attention Customer Relations", "FAO the Registrar": who it is for there
    while part and part[0].word in _ATTENTION:
        part = part[1:]
    if (
        not part
        or len(part) > (_STREET_WORDS if _numbered(part) else _TAIL_WORDS)
        or any(_a_person(tokens, n, k, names) for n in range(end, k))
    ):
        return end
    if any(language.is_weekday(t.word) or language.is_month(t.word) for t in part):
        return end  # "to Ofcom, Monday": when, not where
    # "School of Pharmacy": a proper name's small joining words are part of the place too
    first = k - len(part)
    glued = [_hyphen_glued(gaps, n) for n in range(first, k)]
    if all(g or _place_word(t) for g, t in zip(glued, part, strict=True)):
        return k
    if _proper_name([t for g, t in zip(glued, part, strict=True) if not g]):
        return k
    return end


def _hyphen_glued(gaps: Sequence[str], n: int) -> bool:
    """Whether token ``n`` is joined to the word before it by a bare hyphen: the lower-case
    parts of a hyphenated place name ("Minato-ku", "Aix-en-Provence", "Stratford-upon-Avon")
    belong to the capitalised word they hang on, as its own letters do."""
    return 0 < n < len(gaps) and gaps[n] == "-"


def _numbered(part: Sequence[Token]) -> bool:
    """Whether an address's part after a comma is a numbered line ("Unit 4 Dockside Road",
    "14 Quay Road"): a number and, but for it, capitalised words only."""
    return any(t.text.isdigit() for t in part) and all(
        t.text.isdigit() or t.text[:1].isupper() for t in part
    )


def _numbers_only(tokens: Sequence[Token], gaps: Sequence[str], end: int, stop: int) -> bool:
    """Whether the part after the comma at ``end`` is only a number to dial ("Dr Osei's
    clinic, 01632 960442"): the place's phone or fax number, said after it; the destination
    goes on over it, whatever the words before the comma look like."""
    k = end
    while k < stop and (k == end or not _ends(gaps[k])) and tokens[k].word not in _END_WORDS:
        if not tokens[k].text.isdigit():
            return False
        k += 1
    # a number to dial has some digits: "the clinic, 3 please" may be how many
    return sum(len(t.text) for t in tokens[end:k]) >= _DIALLED_DIGITS


def _street_line(first: Sequence[Token]) -> bool:
    """Whether the words after a comma open a street address, a house number and then a
    capitalised name ("Channel Nine legal, 12 Harbour Road"): the place before it may be
    said in lower case, and still the address goes on."""
    return len(first) == 2 and first[0].text.isdigit() and first[1].text[:1].isupper()


def _a_person(tokens: Sequence[Token], n: int, stop: int, names: Collection[int]) -> bool:
    """Whether token ``n`` of an address's part names someone of the office: a name followed
    by a number or code names a part of the place ("St Luke's, Ward 4" where a colleague is
    called Ward; "Block 7"), not the colleague."""
    if n not in names:
        return False
    after = n + 1
    while after < stop and after in names:
        after += 1
    return not (after < stop and any(c.isdigit() for c in tokens[after].text))


def _place_word(token: Token) -> bool:
    """Whether a word after an address's comma may be part of the place: a name, a code or a
    number ("Leeds", "LS1", "4"), or a noun that names a part of it ("pharmacy", "reception"),
    never a pronoun nor a word that opens a clause ("it", "then")."""
    if token.text[:1].isupper() or any(c.isdigit() for c in token.text):
        return True
    return token.word not in _NOT_PLACE and language.is_noun(token.word)


# The words that open an address line naming who it is for ("attention Customer Relations").
_ATTENTION = frozenset({"attention", "attn", "fao", "att", "the"})


def _address_after(
    tokens: Sequence[Token], gaps: Sequence[str], end: int, stop: int
) -> tuple[int, int] | None:
    """ "post it to the customer please, *Mrs Patel at 14 Elm Road*": after the destination
    (and a "please"), a comma, then to the clause's end an address said in full (a name "at"
    a house number, all capitalised words and numbers), which names the place the words
    before only described. None when anything else follows."""
    k = end
    while k < stop and tokens[k].word in ("please", "pls"):
        k += 1
    if k >= stop or gaps[k].strip() != ",":
        return None
    last = k
    while last < stop and (last == k or not _ends(gaps[last])):
        last += 1
    part = tokens[k:last]
    if last != stop or len(part) < 3 or not part[0].text[:1].isupper():
        return None
    at = next((n for n, t in enumerate(part) if t.word == "at"), None)
    if at is None or at == 0 or not any(c.isdigit() for c in part[at + 1].text):
        return None
    spelled = [t for n, t in enumerate(part) if n != at]
    if not all(t.text[:1].isupper() or any(c.isdigit() for c in t.text) for t in spelled):
        return None
    return k, last


# Small words a place's proper name may hold between its capitalised words ("the Bank of
# England", "Marks and Spencer").
_NAME_JOINS = frozenset({"the", "of", "and", "&", "for", "on", "upon", "de", "la"})


# The words that may open a role said before its holder's name ("the agent, Harrow Homes")
_ROLE_OPENERS = frozenset({"the", "our", "their", "my", "his", "her"})


def _role_named(tokens: Sequence[Token], gaps: Sequence[str], start: int, end: int) -> bool:
    """ "to the agent, Harrow Homes, 3 Kiln Lane": a role said first (a determiner and at
    most two lower-case nouns), then after its comma the proper name of who holds it; the
    name and the address after it are the destination too."""
    comma = next((k for k in range(start + 1, end + 1) if gaps[k].strip() == ","), None)
    if comma is None or comma >= len(tokens) or not 2 <= comma - start <= 3:
        return False
    role = tokens[start:comma]
    if role[0].word not in _ROLE_OPENERS:
        return False
    if not all(t.text[:1].islower() and language.is_noun(t.word) for t in role[1:]):
        return False
    return tokens[comma].text[:1].isupper()


def _proper_name(words: Sequence[Token]) -> bool:
    """Whether the words are a proper name: each capitalised (or a code), but for the small
    joining words, and at least one capitalised."""
    capitalised = [t.text[:1].isupper() or any(c.isdigit() for c in t.text) for t in words]
    return any(capitalised) and all(
        c or t.word in _NAME_JOINS for c, t in zip(capitalised, words, strict=True)
    )


def _which_one(
    tokens: Sequence[Token], gaps: Sequence[str], start: int, end: int, stop: int
) -> tuple[int, str | None] | None:
    """A destination said as a kind of place, then which one after the comma at ``end``
    ("the lab, the Bristol one", "the lab, the one in Bristol"): the place said whole ("the
    Bristol lab", "the lab in Bristol") and where the words end; no place (asked) when the
    words after the comma say more than which one ("the Bristol one or the Bath one"); None
    when the comma is followed by no "the ... one"."""
    if gaps[end].strip() != "," or tokens[start].word != "the" or tokens[end].word != "the":
        return None
    kind = tokens[start + 1 : end]
    if not kind or any(t.text[:1].isupper() for t in kind):
        return None
    clause = end + 1
    while clause < stop and not _ends(gaps[clause]) and tokens[clause].word not in _END_WORDS:
        clause += 1
    said = tokens[end + 1 : clause]
    if "one" not in [t.word for t in said]:
        return None
    plain = " ".join(t.text for t in kind)
    names = [t.text for t in said[:-1]]
    if said[-1].word == "one" and names and all(n[:1].isupper() for n in names):
        return clause, f"the {' '.join(names)} {plain}"  # "the Bristol one"
    where = [t.text for t in said[2:]]
    if [t.word for t in said[:2]] in (["one", "in"], ["one", "at"]) and where:
        if all(n[:1].isupper() for n in where):  # "the one in Bristol"
            return clause, f"the {plain} {said[1].text} {' '.join(where)}"
    return clause, None


def _pronoun_object(words: Sequence[str], verb_end: int) -> bool:
    """Whether the send-out verb's object is a pronoun ("can you courier *it*"): the item was
    named before, in a statement that may also say where it goes."""
    return verb_end < len(words) and words[verb_end] in _PRONOUNS


def _stated_before(words: Sequence[str], gaps: Sequence[str], verb_start: int) -> int | None:
    """The "to" of a statement before the request that says where the item goes ("the parcel
    ... needs to go out *to* the sister hotel, can you courier it"): the last "to" after a
    word of going in an earlier clause of its sentence or the one before (never an infinitive's
    "to": "needs *to* go")."""
    sentences = 0
    for k in range(verb_start - 1, 0, -1):
        if any(c in ".!?;\n" for c in gaps[k + 1]):
            sentences += 1
            if sentences > 1:
                return None  # only the sentence just before says what "it" is
        if words[k] == "to" and words[k - 1] in _GOING and not _ends(gaps[k]):
            return None if _person_goes(words, gaps, k) else k
    return None


def _person_goes(words: Sequence[str], gaps: Sequence[str], to: int) -> bool:
    """Whether the clause of the statement's "to" is about a person going ("*I*'m going to
    the bank, can you fax it"): then its place is where they go, never where the item goes."""
    k = to - 1
    while k > 0 and not _ends(gaps[k]):
        k -= 1
    return any(w in _PERSONS for w in words[k:to])


def _to_before(words: Sequence[str], gaps: Sequence[str], means: int) -> int | None:
    """The "to" before a service named as the means of sending ("to the arts council *by
    courier*"), in the same clause."""
    for k in range(means - 1, -1, -1):
        if _ends(gaps[k + 1]):
            return None
        if words[k] == "to":
            return k
    return None


def _next_clause(words: Sequence[str], k: int) -> bool:
    """Whether ``words[k]`` joins the request's next clause of handing or telling onto the
    destination ("and let me know", "and then bring me ..."), one not about the item sent."""
    if words[k] != "and":
        return False
    nxt = list(words[k + 1 : k + 4])
    if nxt[:1] == ["then"]:
        nxt = nxt[1:]
    # "and bring it back": more done with the item sent out, which cannot be; left unread
    return bool(nxt) and nxt[0] in _HANDING and nxt[1:2] != [] and nxt[1] not in _PRONOUNS


def _bracketed(said: str) -> str:
    """ "the exam board (WJEC)": the name in brackets is the place's own name."""
    if "(" not in said:
        return said
    inner = said.split("(", 1)[1].split(")", 1)[0].strip()
    return inner or said.replace("(", "").replace(")", "").strip()


def _ends(gap: str) -> bool:
    return any(c in _END_MARKS for c in gap)


# Words that only say a place is elsewhere, never which place ("the *outside* lab").
_ELSEWHERE = frozenset({"outside", "external", "offsite", "off", "site", "other", "somewhere"})
_ARTICLES = frozenset({"the", "a", "an", "some", "one", "our"})


def only_describes(phrase: str, asked: str) -> bool:
    """Whether a destination ``phrase`` only describes the kind of place the service asks
    for (``asked``: "which lab") without naming one ("the outside lab", "an external lab"): no
    capitalised word, and no word beyond an article, the question's own words and words of
    being elsewhere. Such a phrase is no destination; the place is asked."""
    said = phrase.replace("-", " ").split()
    if not said or any(w[:1].isupper() or not w.isalpha() for w in said):
        return False
    question = set(language.fold(asked).replace(",", " ").split())
    return all(w in _ARTICLES | _ELSEWHERE | question for w in said)


# A place's name said right after a description of it ("the outside lab, Northgate Labs please").
_NAMED_AFTER = re.compile(
    r"^\s*[,:(\u2013\u2014-]\s*([A-Z][\w&'.]*(?:\s+(?:[A-Z][\w&'.]*|&|of|and))*)"
)


def named_after(text: str, phrase: str) -> str | None:
    """The capitalised name said right after a described destination in ``text``, if any."""
    at = text.find(phrase)
    if at < 0:
        return None
    found = _NAMED_AFTER.match(text[at + len(phrase) :])
    name = found.group(1).rstrip(" .") if found else ""
    return name if name and name.split()[-1] not in ("and", "of", "&") else None


def names_no_place(phrase: str, service_words: Iterable[str]) -> bool:
    """Whether a destination is said only in the service's own words ("send it off to the
    cleaners" where the service is "send to the cleaners"): the kind of place every such
    send-out goes to, not which one; the requester is asked, never a guess."""
    said = {_singular(w) for w in language.words(phrase)} - _MEANS_ARTICLES - {"an"}
    own = {_singular(w) for text in service_words for w in language.words(text)}
    return bool(said) and said <= own


def _singular(word: str) -> str:
    nouns = language.lemmas(word).get("NOUN", ())
    return nouns[0] if nouns else word
