"""Which item mentions of a clause are the objects of its request, and which only modify it.

The object of a request is the head noun the request verb acts on; other item words in the
clause say when, what for, or where, and must never become tasks of their own:

- a time phrase, a bare noun after a time preposition: "a book to read *over lunch*",
  "*after lunch* bring me some paper";
- a modifier phrase after the object: "a mug *for my coffee*", "a pen *with* ...";
- a purpose clause after the object: "a book *to read* on the train", "a pen *to sign my
  contract* with" (a purpose verb with an object of its own is not the request either, so its
  task word does not count; "take my contract to Zhang *to sign*" keeps it);
- a reason clause after the object: "a radio *because there's no money for new headlamps*";
- a statement about an owned item after the object: "a radio *as my headlamp is dying*";
- a container or measure word before "of": "a *cup of* coffee" is coffee;
- an item word right before another ("the *draft* contract"): the last noun is the head.
- a purpose phrase after a product or a pronoun that is the object: "I need a copy *for the
  file*", "I need one *for the rota*" (the product's noun, "one" or "it" is what is asked
  for; the item word after "for the" says what it is for, never a second object).

Objects joined by "and", "or" or commas ("a stapler and a coffee", "scissors, a pen and some
wipes") are all objects of the same verb. (An item word used as a verb, "book me a taxi", was
already read as a plain word by the readings stage.)
"""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language

# Prepositions of time: a bare noun after one is a time phrase ("over lunch", "at lunch").
TIME_PREPOSITIONS = english.words("time_prepositions")
# Prepositions that attach a phrase to the object before them ("a mug for my coffee").
# Not "of" (the object's own complement: "a copy of my contract"), "on" ("the seal on my
# form"), "from"/"to"/"by" (people's roles).
MODIFIER_PREPOSITIONS = english.words("object_modifier_prepositions")
DETERMINERS = english.words("determiners")
# Conjunctions that open a reason clause: what it names explains the request, never joins it.
REASON_CONJUNCTIONS = english.words("reason_conjunctions")
STATE_VERBS = english.words("state_verbs")
# The verbs of everyday services, some of them nouns the dictionary has no verb for ("to
# courier"): after "to", a purpose, never a place.
_SERVICE_VERBS = english.words("service_verbs")
# The words before a file type that name a product's format ("to PDF", "into a PDF").
_FORMAT_LINKS = frozenset({"to", "into", "as"})
_ARTICLES = frozenset({"a", "an", "another"})
# The task kinds whose work is a product named like the service ("a copy", "a print").
_PRODUCT_KINDS = frozenset({"print", "copy"})
# What links an occasion to the thing wanted for it ("for the signing", "before the printing");
# not a place's "in"/"at" ("chuck it in the recycling": where it goes)
_OCCASION_LINKS = frozenset({"for", "before", "after", "during"})
# What opens an occasion named by an operation's noun ("for *the* audit")
_OCCASION_DETERMINERS = frozenset({"the", "this", "that", "our", "tomorrows", "todays"})
# What says a thing is the speaker's own ("my stopwatch"): its work may be what is asked
_SPEAKERS = frozenset({"my", "our"})


def modifiers(
    tokens: Sequence[Token],
    mentions: Sequence[Mention],
    sourced: frozenset[str] = frozenset(),
    formats: frozenset[str] = frozenset(),
) -> set[int]:
    """Start tokens of the clause's item, cue and facility mentions that are not its request.
    ``sourced``: the products made from an item ("a copy of my form"); ``formats``: the file
    types, which after "to"/"into"/"as" in a clause that asks to copy or print name the
    format of what is made ("scan my contract to PDF"), never a thing or a person."""
    out: set[int] = set()
    making = any(m.kind == "cue" and {"copy", "print"} & set(m.ids) for m in mentions)
    head_seen = False
    in_purpose = False
    infinitive = False  # the purpose is an infinitive's ("a book to read")
    moved_there = False  # the purpose's verb moves the thing ("needs to go in the annealer")
    occasions = [
        (start, m.start)
        for m in mentions
        if m.kind == "cue"
        and (start := _occasion_gerund(tokens, m) or _occasion_noun(tokens, mentions, m))
        is not None
    ]
    for n, m in enumerate(mentions):
        if in_purpose and infinitive and m.kind == "item" and _second_thing(tokens, m):
            in_purpose = infinitive = False  # "paper to write on, and a pen": a pen too
        if in_purpose:
            # "a multimeter to check the compressor's wiring": the facility is where the
            # thing is used, no service asked of it ("it needs to go in the annealer": to it)
            if m.kind in ("item", "cue") or (m.kind == "facility" and not moved_there):
                out.add(m.start)
            continue
        if m.kind == "word" and m.ids[0] == "to" and head_seen and _purpose(tokens, mentions, n):
            in_purpose = infinitive = True
            verb = tokens[m.end].word if m.end < len(tokens) else ""
            # "my samples need to sit in the drying cabinet": what the thing itself needs,
            # said before "to", is the facility's work, not a use of the thing there
            own_need = m.start > 0 and bool(
                language.verb_lemmas(tokens[m.start - 1].word) & _THINGS_NEED
            )
            moved_there = own_need or bool(language.verb_lemmas(verb) & _PLACE_MOVING)
            continue
        asked = head_seen or any(c.kind == "cue" for c in mentions[:n])
        if asked and m.kind in ("item", "cue") and any(a <= m.start <= b for a, b in occasions):
            out.add(m.start)  # "Wang's stapler for the contract signing": an occasion, why
            continue
        if (
            m.kind == "word"
            and asked
            and (m.ids[0] in REASON_CONJUNCTIONS or _reason_as(tokens, m))
        ):
            in_purpose = True  # "... because there's no money for new stopwatches": context
            continue
        if m.kind == "word" and head_seen and _use_gerund(tokens, mentions, n):
            in_purpose = True  # "tissue paper for packing a veil": the veil is its use
            continue
        if asked and _object_word(tokens, m):
            head_seen = True  # "I need a copy for the file": the copy is what is asked for
            continue
        if m.kind != "item":
            continue
        if asked and _subject_of_state(tokens, mentions, n):
            in_purpose = True  # "..., as my headlamp is dying": a reason said as a statement
            out.add(m.start)
            continue
        compound = n > 0 and mentions[n - 1].start in out and mentions[n - 1].end == m.start
        if making and m.id in formats and _after(tokens, m, _FORMAT_LINKS):
            out.add(m.start)  # "to PDF", "into a pdf", "as a PDF"
        elif _compound_modifier(mentions, n):
            out.add(m.start)  # "my draft contract": the head is the last noun, "contract"
        elif _time_phrase(tokens, m) or (head_seen and (_modifier_phrase(tokens, m) or compound)):
            out.add(m.start)  # "a copy for the contract file": the whole noun is the purpose
        elif _container(tokens, mentions, n, sourced):
            out.add(m.start)
        else:
            head_seen = True
    return out


def _use_gerund(tokens: Sequence[Token], mentions: Sequence[Mention], n: int) -> bool:
    """Whether mention ``n`` is "for" before a doing that is no task of the office's ("for
    packing a veil", "for wrapping the gifts"), as "to pack a veil" is: what the thing asked
    for is used on; a task's own gerund ("for printing") is read as before."""
    m = mentions[n]
    if m.ids[0] != "for" or n + 1 >= len(mentions):
        return False
    nxt = mentions[n + 1]
    word = tokens[nxt.start].word if nxt.start < len(tokens) else ""
    return (
        nxt.kind == "word"
        and nxt.start == m.end
        and word.endswith("ing")
        and language.is_present_participle(word)
    )


# The words that open a second thing after a purpose infinitive ("..., and *a* pen")
_SECOND_THING = english.words("second_thing_articles")


def _second_thing(tokens: Sequence[Token], m: Mention) -> bool:
    """ "i need some paper to write on, and a pen", "a book to read and a water": after a
    purpose infinitive, "and" with an article opens a second thing of the request (the
    infinitive's own objects have none: "a pen to sign my contract and letter with")."""
    k = m.start - 1
    while k >= 0 and tokens[k].word in _SECOND_THING:
        k -= 1
    return k + 1 < m.start and k >= 0 and tokens[k].word == "and"


def _after(tokens: Sequence[Token], m: Mention, words: frozenset[str]) -> bool:
    """Whether the word before ``m`` (past an article) is one of ``words``."""
    k = m.start - 1
    while k >= 0 and tokens[k].word in ("a", "an", "the"):
        k -= 1
    return k >= 0 and tokens[k].word in words


def _compound_modifier(mentions: Sequence[Mention], n: int) -> bool:
    """ "the draft contract", "my report file": an item word right before another item word
    (nothing between) modifies it; the last one names the thing."""
    nxt = mentions[n + 1] if n + 1 < len(mentions) else None
    return nxt is not None and nxt.kind == "item" and nxt.start == mentions[n].end


def _object_word(tokens: Sequence[Token], m: Mention) -> bool:
    """A request's object that is no item of its own: the name of a service's product used
    as a noun after an article ("a copy", "a print"), or "one" standing for the item."""
    if m.kind == "cue":
        after_article = m.start > 0 and tokens[m.start - 1].word in _ARTICLES
        return after_article and bool(m.ids) and set(m.ids) <= _PRODUCT_KINDS
    return m.kind == "word" and m.ids[0] == "one"


_PLACE_MOVING = english.words("place_moving_verbs")
_THINGS_NEED = frozenset({"need", "have", "want", "ought"})


def _purpose(tokens: Sequence[Token], mentions: Sequence[Mention], n: int) -> bool:
    """ "to" + a verb: a purpose clause, unless the verb is a task word without its own object
    ("to the arts council": an article after "to" opens a place, not a verb)."""
    nxt = mentions[n + 1] if n + 1 < len(mentions) else None
    after = mentions[n].end
    if nxt is None or (after < len(tokens) and tokens[after].word in DETERMINERS):
        return False
    if nxt.kind == "word" and nxt.ids[0] == "be":
        return False  # "my plan needs to be bound": a passive, the service asked for
    if nxt.kind == "word":
        # "to Hartwell & Co": a capitalized word that is no verb names a place, not a purpose
        named = nxt.text[:1].isupper() and not language.verb_lemmas(nxt.ids[0])
        # "to microbiology by the tube": a noun that is never a verb names a place
        place = (
            not language.verb_lemmas(nxt.ids[0])
            and nxt.ids[0] not in _SERVICE_VERBS
            and language.is_noun(nxt.ids[0])
        )
        return nxt.ids[0] not in DETERMINERS and not nxt.ids[0].isdigit() and not (named or place)
    if nxt.kind == "cue":
        return any(m.kind == "item" for m in mentions[n + 2 :])
    return False


# The subjects after which "as" opens a reason ("..., as he prefers it on paper"), never the
# "as" of a manner or a comparison ("as soon as you can", "as a PDF")
_REASON_AS_SUBJECTS = english.words("subject_pronouns") - english.words("addressee_pronouns")


def _reason_as(tokens: Sequence[Token], m: Mention) -> bool:
    """ "print my report for Mao as he prefers it on paper": "as" then a subject pronoun and
    a word after it opens a reason clause, like "because"; what it names is context."""
    k = m.start
    return (
        tokens[k].word == "as"
        and k + 2 < len(tokens)
        and tokens[k + 1].word in _REASON_AS_SUBJECTS
        and tokens[k + 2].word.isalpha()
    )


def _subject_of_state(tokens: Sequence[Token], mentions: Sequence[Mention], n: int) -> bool:
    """ "my headlamp is dying": an owned item followed by a state verb is the subject of a
    statement about it, not an object of the request."""
    m = mentions[n]
    before = mentions[n - 1] if n else None
    owned = before is not None and before.possessive and before.end == m.start
    return owned and m.end < len(tokens) and tokens[m.end].word in STATE_VERBS


def _time_phrase(tokens: Sequence[Token], m: Mention) -> bool:
    return m.start > 0 and tokens[m.start - 1].word in TIME_PREPOSITIONS


# Plain words that may describe the item between its determiner and it ("for the *grant*
# report", "for my *quarterly* report")
_DESCRIBING_WORDS = 2


def _modifier_phrase(tokens: Sequence[Token], m: Mention) -> bool:
    """ "a mug for my coffee", "paper for the grant report": the item after a modifying
    preposition, past its determiner or possessive and up to two describing words after
    that determiner (never bare words: "for Zhang Wei's" is a person's)."""
    k = m.start - 1
    j = k
    while j >= 0 and k - j < _DESCRIBING_WORDS and _describing(tokens[j]):
        j -= 1
    if j < k and j >= 0 and (tokens[j].word in DETERMINERS or tokens[j].possessive):
        k = j  # "the grant report": the determiner before the describing words
    while k >= 0 and (tokens[k].word in DETERMINERS or tokens[k].possessive):
        owner = tokens[k].possessive
        k -= 1
        j = k
        while owner and j >= 0 and k - j < _DESCRIBING_WORDS and _describing(tokens[j]):
            j -= 1
        if j < k and j >= 0 and tokens[j].word in DETERMINERS:
            k = j  # "for a new starter's badge": the owner's describing words and determiner
    return k >= 0 and tokens[k].word in MODIFIER_PREPOSITIONS


def _occasion_gerund(tokens: Sequence[Token], m: Mention) -> int | None:
    """ "borrow Wang's stapler for the contract signing at 3", "a pen for the signing": a
    task word's "-ing" form that ends a noun phrase opened by a determiner after "for" (or
    "before"/"after"/"during") names an occasion (why or when the thing is wanted), never
    work asked, and the things its phrase names ("contract") are none asked for either: the
    phrase's first token, or None. "for signing" with no determiner ("take my contract to Wang for
    signing") and "the printing schedule" (a noun after it: the gerund only modifies that
    noun) are no occasion."""
    word = tokens[m.start].word
    lemmas = language.verb_lemmas(word)
    if m.end != m.start + 1 or not word.endswith("ing") or not lemmas or word in lemmas:
        return None
    nxt = tokens[m.end] if m.end < len(tokens) else None
    if nxt is not None and not nxt.opens and not nxt.after_pause and _noun_after(nxt.word):
        return None
    k = m.start - 1
    j = k
    while j >= 0 and k - j < _DESCRIBING_WORDS and _describing(tokens[j]):
        j -= 1
    if j < 1 or tokens[j].word not in DETERMINERS or tokens[j - 1].word not in _OCCASION_LINKS:
        return None
    return j


def _occasion_noun(tokens: Sequence[Token], mentions: Sequence[Mention], m: Mention) -> int | None:
    """ "can someone lend me a stopwatch for the fitness test", "a stapler for the 3pm
    review": an operation's noun that ends a noun phrase opened by "the" (or "this", "that",
    "our") after "for"/"before"/"after"/"during", right after a thing asked for that is not
    the speaker's own, names an occasion (why the thing is wanted), as the "-ing" form does
    (``_occasion_gerund``): the phrase's first token, or None. "test my stopwatch for the
    fitness test" (no thing before the phrase) and "take my stopwatch to the lab for the
    test" (the speaker's own thing, whose work it may be) are no such occasion."""
    word = tokens[m.start].word
    if m.end != m.start + 1 or word.endswith("ing") or "NOUN" not in language.lemmas(word):
        return None
    nxt = tokens[m.end] if m.end < len(tokens) else None
    if nxt is not None and not nxt.opens and not nxt.after_pause and _noun_after(nxt.word):
        return None
    j = m.start - 1
    while j >= 0 and m.start - 1 - j < _DESCRIBING_WORDS and _said_of_an_occasion(tokens[j]):
        j -= 1
    if j < 2 or tokens[j].word not in _OCCASION_DETERMINERS:
        return None
    if tokens[j - 1].word not in _OCCASION_LINKS:
        return None
    thing = [t for t in mentions if t.kind == "item" and t.end == j - 1]
    if not thing or _speakers_own(tokens, thing[0]):
        return None
    return j


def _said_of_an_occasion(token: Token) -> bool:
    """A word that may describe an occasion before its noun: a plain word or a time ("3pm")."""
    word = token.word
    if word in DETERMINERS or word in _OCCASION_DETERMINERS or word in _OCCASION_LINKS:
        return False
    return _describing(token) or (word.isalnum() and any(c.isdigit() for c in word))


def _speakers_own(tokens: Sequence[Token], thing: Mention) -> bool:
    """Whether an owner word of the speaker opens the phrase of ``thing`` ("my stopwatch")."""
    k = thing.start - 1
    while k >= 0 and thing.start - k <= _DESCRIBING_WORDS and _describing(tokens[k]):
        k -= 1
    return k >= 0 and tokens[k].word in _SPEAKERS


def _noun_after(word: str) -> bool:
    """Whether ``word`` may be the noun a gerund before it modifies ("printing *schedule*"),
    not a preposition or a time that follows the phrase ("signing *at* 3")."""
    return "NOUN" in language.lemmas(word) and word not in MODIFIER_PREPOSITIONS


def _describing(token: Token) -> bool:
    """A plain word that may stand between an item's determiner and the item."""
    word = token.word
    return (
        word.isalpha()
        and not token.possessive
        and not token.after_pause
        and word not in DETERMINERS
        and word not in MODIFIER_PREPOSITIONS
        and word not in TIME_PREPOSITIONS
    )


def _container(
    tokens: Sequence[Token], mentions: Sequence[Mention], n: int, sourced: frozenset[str]
) -> bool:
    """ "a cup of coffee": the item before "of" another item only measures it; not a product
    made from what follows "of" (``sourced``: "a copy of my form")."""
    m = mentions[n]
    if m.id in sourced or m.end >= len(tokens) or tokens[m.end].word != "of":
        return False
    for after in mentions[n + 1 :]:
        if after.kind == "item":
            return True
        if after.kind != "word" or after.ids[0] not in DETERMINERS | {"of"}:
            return False
    return False
