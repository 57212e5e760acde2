"""An office operation named by a verb and its object ("apply corrections", "update the
register"), asked for with other words between them: "apply this week's corrections to my
charts pls", "could you update the tide register for me".

The office names such an operation by what is done and to what. Word by word, the verb
("apply", "update") is nobody's verb and the rest reads as something handed "to" the
thing ("Who should get your chart?"). So the request is matched to the operation by the
lemmas of the name's own verb and its object's head noun, in that order and within a short
clause, whatever stands between them ("this week's", "the latest Notices to Mariners");
the verb is then read as the operation's own phrase (``verb_phrases`` joins and reads it),
the object's words go (they name the work, not a thing to fetch), and the thing the work is
done "to" is the item worked on ("to my charts": the charts, which come back to their
owner). Where the object is the very thing the operation works on ("update the register"
for an operation on registers), it stays, as the item.

Only operations that work on an item (an ``input``) are named so, and only by their own
names and declared phrases; a name whose object is another thing of the office ("print
spine labels": the labels made) is left to the readings of products.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language
from assistantx.core.office import Office
from assistantx.memory.names import normalize

_ARTICLES = frozenset({"a", "an", "the"})
_FUNCTION_WORDS = english.words("common")
# The most words from the verb to its object: "apply *this week's Notices to Mariners*
# corrections" (a title of a few words, a possessive) but not across a clause.
_REACH = 8
# Words that join a verb to a complement, never an object's ("run *through* the dishwasher").
_PREPOSITIONS = frozenset(
    {"to", "into", "in", "on", "onto", "at", "with", "from", "for", "by", "through", "via"}
    | {"over", "under", "off", "out", "up", "down", "across", "around", "round"}
)
# Words that end the clause the verb opens: its object is not past them.
_CLAUSE_ENDS = frozenset({"and", "then", "but", "or", "so", "because", "if", "when"})
# The words that say what the work is done to: "apply corrections *to* my charts",
# "remove the staples *from* my report".
_DONE_TO = frozenset({"to", "onto", "on", "in", "from"})
# What may stand between "to" and the thing: "to *my* charts", "to *all of the* charts".
_THING_REACH = 4


def key(phrase: str) -> str:
    return normalize(phrase.replace("-", " "))


def _noun_lemmas(word: str) -> frozenset[str]:
    return frozenset((word, *language.lemmas(word).get("NOUN", ())))


@dataclass(frozen=True)
class WorkName:
    """One operation's name of a verb and an object."""

    operation: str
    phrase: str  # the name as one token's word ("apply corrections")
    verb: str  # the verb's lemma ("apply")
    head: str  # the object's head noun, singular ("correction")
    on_input: bool  # the object is the thing the operation works on ("the register")
    inputs: frozenset[str]  # the head nouns of that thing's names ("chart")


def work_names(office: Office) -> tuple[WorkName, ...]:
    """The office's operation names made of a verb and an object, each phrase one
    operation's only (a phrase two operations share names neither)."""
    things = {key(n) for t in office.item_types for n in (t.name, *t.synonyms)}
    found: dict[str, list[WorkName]] = {}
    for op in office.operations:
        if op.input is None:
            continue
        item = office.item_type(op.input)
        inputs = frozenset(
            lemma
            for name in (item.id.replace("_", " "), item.name, *item.synonyms)
            if (words := key(name).split())
            for lemma in _noun_lemmas(words[-1])
        )
        # the verbs that already ask for it alone ("dry" of "dry kit"): nothing to match
        own = {normalize(v).split()[0] for v in op.verbs if " " not in v.strip()}
        for phrase in dict.fromkeys((*op.verbs, op.name)):
            name = _work_name(op.id, phrase, inputs, things)
            if name is not None and name.verb not in own:
                found.setdefault(name.phrase, []).append(name)
    return tuple(names[0] for names in found.values() if len(names) == 1)


def _work_name(
    op_id: str, phrase: str, inputs: frozenset[str], things: set[str]
) -> WorkName | None:
    """``phrase`` (as the office wrote it) read as a verb and its object, if it is one."""
    said = phrase.lower().replace("-", " ").split()  # as written, its articles kept
    words = key(phrase).split()
    if len(words) < 2 or "VERB" not in language.lemmas(words[0]) or _compound(said):
        return None
    obj = [w for w in words[1:] if w not in _ARTICLES]
    if not obj or any(w in _FUNCTION_WORDS or w in _PREPOSITIONS for w in obj):
        return None  # "seal in plastic", "run through the dishwasher": a complement
    nouns = language.lemmas(obj[-1]).get("NOUN", ())
    if not nouns:
        return None  # no object named
    head = nouns[0]
    on_input = head in inputs
    if not on_input and " ".join(obj) in things:
        return None  # "print spine labels": the thing made, read as a product
    verbs = language.verb_lemmas(words[0]) or frozenset({words[0]})
    return WorkName(op_id, " ".join(words), min(verbs), head, on_input, inputs)


def _compound(words: Sequence[str]) -> bool:
    """ "vacuum seal", "dry clean": a compound verb (its last word a verb's plain form, no
    function word), which ``verb_phrases`` joins and reads; no verb and object ("apply asset
    tags": a plural noun last; "update the register": an article before it)."""
    last = words[-1]
    plain_verb = last in language.verb_lemmas(last)
    return plain_verb and not any(w in _FUNCTION_WORDS for w in words)


@dataclass(frozen=True)
class NamedWork:
    """Reads the office's verb-and-object operation names in a message's tokens."""

    names: tuple[WorkName, ...]
    # the office's things named in several words ("diagnostics rig"): a word inside one is
    # that thing's, never the work's object ("run my phone through the diagnostics rig")
    things: frozenset[tuple[str, ...]] = frozenset()

    @classmethod
    def from_office(cls, office: Office) -> NamedWork:
        names = (
            *(n for f in office.facilities for n in (f.name, *f.synonyms)),
            *(n for t in office.item_types for n in (t.name, *t.synonyms)),
        )
        things = frozenset(tuple(w) for n in names if len(w := key(n).split()) > 1)
        return cls(work_names(office), things)

    def phrases(self) -> dict[str, str]:
        """Each name's phrase → its operation: the verb token's word once read."""
        return {n.phrase: n.operation for n in self.names}

    def read(self, tokens: Sequence[Token]) -> list[Token]:
        """``tokens`` with each operation named by verb and object read as its phrase."""
        out = list(tokens)
        if not self.names:
            return out
        n = 0
        while n < len(out):
            t = out[n]
            verbs = language.verb_lemmas(t.word) | {t.word}
            for name in self.names:
                if name.verb not in verbs or t.possessive:
                    continue
                at = _object_at(out, n, name.head, self.things)
                if at is None:
                    continue
                out[n] = t.corrected_to(name.phrase)
                if not name.on_input:
                    # the object's words name the work: gone, and the "to" before the thing
                    # worked on with them ("apply corrections *to* my charts")
                    del out[n + 1 : at + 1]
                    if _done_to(out, n + 1, name.inputs):
                        del out[n + 1]
                break
            n += 1
        return out


def _object_at(
    tokens: Sequence[Token], n: int, head: str, things: frozenset[tuple[str, ...]] = frozenset()
) -> int | None:
    """Where the object's head noun stands after the verb at ``n``, within its clause; a
    word of a thing's name of several words is that thing's ("the diagnostics rig")."""
    for k in range(n + 1, min(len(tokens), n + 1 + _REACH)):
        t = tokens[k]
        if t.opens or t.word in _CLAUSE_ENDS or (t.after_pause and k > n + 1):
            return None
        if not t.possessive and head in _noun_lemmas(t.word) and not _in_thing(tokens, k, things):
            return k
    return None


def _in_thing(tokens: Sequence[Token], k: int, things: frozenset[tuple[str, ...]]) -> bool:
    """Whether ``tokens[k]`` is a word of one of ``things`` said there."""
    words = [t.word for t in tokens]
    return any(
        tuple(words[start : start + len(thing)]) == thing
        for thing in things
        for start in range(max(0, k - len(thing) + 1), k + 1)
    )


def _done_to(tokens: Sequence[Token], at: int, inputs: frozenset[str]) -> bool:
    """Whether ``tokens[at]`` is "to" before the thing the operation works on."""
    if at >= len(tokens) or tokens[at].word not in _DONE_TO:
        return False
    return any(
        inputs & _noun_lemmas(t.word) for t in tokens[at + 1 : at + 1 + _THING_REACH] if not t.opens
    )
