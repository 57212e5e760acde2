"""An operation asked for by a phrase of several words the office declares ("3D print",
"laser cut", "heat press"), read as one verb before anything else reads its words.

An office may declare a verb phrase whose last word is another operation's verb ("3d print"
beside the plotter's "print"), or whose first word is no verb at all ("vinyl cut"). Read word
by word, the shorter verb inside wins and the wrong machine is asked. So the lexicon first
joins each declared phrase said in the text into one token (longest phrase first, its
words as typed: "3D-print", "3-D print" and "3D print" are one phrase), and that token is the
operation's own cue; the shorter verb it holds is no longer a word of the sentence.

The phrases come from the office file only: an operation's compound verbs (words glued
before a verb: "3d print", "heat press"; not a verb with its particle, "send out", whose head
verb already asks and whose other words keep their readings), its verbs with a complement
("write to tape", "seal in plastic": ``complement_verbs``, also said with the object between),
and its name where that is such a compound opening with one of its own verbs and naming no
thing of the office ("laser cut" for an operation asked for by "laser"; never "buy a snack",
whose "snack" is the product to be named). A phrase two operations share is left to be asked
about. Every ordinary form of the phrase asks for it: its head inflected and its last word
inflected ("3D print(s/ed/ing)"). A phrase that is also a facility's or an item's name is a
thing after a determiner, a quantity or a receiver ("at the heat press", "some bubble wrap",
"bring me bubble wrap"), and stays one.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field

from assistantx.agents.symbolic.reading.asking_forms import asking_forms
from assistantx.agents.symbolic.reading.complement_verbs import (
    complement_verb,
    separated_complement,
    tails_of,
)
from assistantx.agents.symbolic.reading.named_work import NamedWork
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language
from assistantx.core.office import Office, Operation
from assistantx.memory.names import normalize

_DETERMINERS = english.words("modifier_determiners")
# What stands before a thing's name but never before a verb: a determiner or a quantity
# ("some bubble wrap", "more bubble wrap"), or the receiver of a verb of giving ("bring me
# bubble wrap"): a declared phrase that is also a thing's name is that thing there
_THING_BEFORE = (
    _DETERMINERS
    | english.words("determiners")
    | frozenset({"more", "extra", "enough", "spare", "us", "him", "them"})
)
_FUNCTION_WORDS = english.words("common")
# The particles of phrasal verbs ("run off", "knock up"): grammar, not any office's words.
_PARTICLES = frozenset({"off", "out", "up", "down", "over", "through", "away", "back"})


def _key(phrase: str) -> str:
    return normalize(phrase.replace("-", " "))


def compound_verb(phrase: str) -> bool:
    """Whether a phrase is a verb with words glued before it ("3d print", "heat press"):
    several words, the last a verb, none a function word. A verb with its particle or
    object ("send out", "seal in plastic") is not: its head verb is read as before, and its
    other words keep their own readings (a destination after "send out")."""
    words = phrase.split()
    if len(words) < 2 or any(w in _FUNCTION_WORDS for w in words):
        return False
    return "VERB" in language.lemmas(words[-1])


def particle_verb(phrase: str, own: Sequence[str]) -> bool:
    """Whether a phrase is a verb and its particle that says more than its head ("run off"
    copies is to print them, where "run" alone runs an errand): two words, the first a verb
    that is none of the operation's own one-word verbs (``own``), the second a particle. Such
    a phrase is the only way it asks for the work, so it is read whole, as a compound is;
    "send out" beside a "send" the operation has keeps its words."""
    words = phrase.split()
    if len(words) != 2 or words[1] not in _PARTICLES or words[0] in own:
        return False
    return "VERB" in language.lemmas(words[0])


def _named_phrases(office: Office, op: Operation, things: set[str]) -> list[str]:
    """The phrases of several words that ask for ``op``: its compound verbs, its verbs with
    a particle whose head alone asks for other work, its verbs with a complement
    (``complement_verbs``), and its name where the name is one that
    opens with one of its own verbs and names no thing."""
    verbs = [_key(v) for v in op.verbs]
    own = [v for v in verbs if " " not in v]
    found = [v for v in verbs if compound_verb(v)]
    found += [v for v in verbs if complement_verb(v)]
    if not op.sends_out:  # a send's destination is read after its verb's words
        found += [v for v in verbs if particle_verb(v, own)]
    name = _key(op.name)
    words = name.split()
    opens_with_own_verb = bool(words) and any(words[0] == v.split()[0] for v in verbs if v)
    names_a_thing = any(
        f" {thing} " in f" {name} " for thing in things if thing and thing not in verbs
    )
    if compound_verb(name) and opens_with_own_verb and not names_a_thing:
        found.append(name)
    return list(dict.fromkeys(found))


def phrase_forms(phrase: str) -> set[str]:
    """Every form of a phrase that can ask for its work: its head inflected ("seals in
    plastic") and its last word inflected ("3d printed")."""
    lead, _, last = phrase.rpartition(" ")
    forms = set(asking_forms(phrase))
    forms |= {f"{lead} {f}" for f in asking_forms(last)}
    return forms


@dataclass(frozen=True)
class VerbPhrases:
    """The office's declared phrases of several words, each form → its operation."""

    forms: dict[str, str]  # "3d printed" → "print3d"
    things: frozenset[str]  # facilities' and items' names: after a determiner, a thing
    longest: int  # words in the longest form
    # each form without its spaces → the form: "3-D print" is typed as "3", "d", "print"
    glued: dict[str, str] = field(default_factory=dict)
    # each head of a verb with a complement → its complements ("write" → ("to", "tape"))
    tails: dict[str, tuple[tuple[str, ...], ...]] = field(default_factory=dict)

    @classmethod
    def from_office(cls, office: Office) -> VerbPhrases:
        things = {_key(n) for f in office.facilities for n in (f.name, *f.synonyms)} | {
            _key(n) for t in office.item_types for n in (t.name, *t.synonyms)
        }
        claimed: dict[str, set[str]] = {}
        complements: list[str] = []
        for op in office.operations:
            for phrase in _named_phrases(office, op, things):
                for form in phrase_forms(phrase):
                    claimed.setdefault(form, set()).add(op.id)
                if complement_verb(phrase):
                    complements += phrase_forms(phrase)
        forms = {form: next(iter(ops)) for form, ops in claimed.items() if len(ops) == 1}
        # "apply corrections": an operation named by its verb and object, its verb read as
        # this one phrase where the object follows it (``named_work``)
        for phrase, op_id in NamedWork.from_office(office).phrases().items():
            forms.setdefault(phrase, op_id)
        glued = {f.replace(" ", ""): f for f in forms}
        longest = max((len(f.split()) for f in forms), default=0) + 1  # "3 d print"
        tails = tails_of([f for f in complements if f in forms])
        return cls(forms, frozenset(things), longest, glued, tails)

    def of_operation(self, op_id: str) -> set[str]:
        return {form for form, op in self.forms.items() if op == op_id}

    def join(self, tokens: Sequence[Token], text: str) -> list[Token]:
        """``tokens`` with each declared phrase said in them joined into one token, longest
        first; the joined token's text is the phrase as typed ("3D-print")."""
        if not self.forms:
            return list(tokens)
        tokens = self._particles_joined(tokens)
        spans = _spans(text, tokens)
        out: list[Token] = []
        n = 0
        while n < len(tokens):
            joined, form = self._phrase_at(tokens, n)
            if joined == 0:
                out.append(tokens[n])
                n += 1
                continue
            parts = tokens[n : n + joined]
            start, end = spans[n][0], spans[n + joined - 1][1]
            flat = text.replace("’", "'")
            out.append(
                Token(
                    text=flat[start:end] if 0 <= start < end else " ".join(t.text for t in parts),
                    word=form,
                    possessive=parts[-1].possessive,
                    typed=" ".join(t.typed or t.word for t in parts),
                    opens=parts[0].opens,
                    after_pause=parts[0].after_pause,
                )
            )
            n += joined
        return out

    def _particles_joined(self, tokens: Sequence[Token]) -> list[Token]:
        """ "run my labels off on the printer": a declared verb with its particle said
        with its object between them, moved next to its verb ("run off my labels"), as
        English lets a particle stand after a short object (``separated_particle``)."""
        out = list(tokens)
        for n in range(len(out)):
            at = separated_particle(out, n, self.forms)
            if at is not None:
                out.insert(n + 1, out.pop(at))
            # "write my file to tape": the complement back next to its verb, likewise
            apart = separated_complement(out, n, self.tails)
            if apart is not None:
                start, size = apart
                moved = out[start : start + size]
                del out[start : start + size]
                out[n + 1 : n + 1] = moved
        return out

    def _phrase_at(self, tokens: Sequence[Token], n: int) -> tuple[int, str]:
        """How many tokens from ``n`` make one declared phrase, and its form (0: none)."""
        for size in range(min(self.longest, len(tokens) - n), 1, -1):
            parts = tokens[n : n + size]
            if any(t.opens for t in parts[1:]) or any(t.possessive for t in parts[:-1]):
                continue  # a phrase does not run over a sentence's end or a possessive
            said = " ".join(t.word for t in parts)
            if said not in self.forms:
                said = self.glued.get(said.replace(" ", ""), "")
            if not said or len(said.split()) > size:
                continue
            if said in self.things and n and tokens[n - 1].word in _THING_BEFORE:
                continue  # "at the heat press", "some bubble wrap": the thing, not the work
            return size, said
        return 0, ""


# The most words of an object between a verb and its particle ("run *my new labels* off").
_OBJECT_WORDS = 4
# Words that end a verb's object: what follows is no longer the thing the verb acts on.
_OBJECT_ENDS = frozenset(
    {"to", "for", "on", "in", "at", "with", "from", "and", "then", "but", "or", "by", "into"}
)


def separated_particle(tokens: Sequence[Token], n: int, forms: Mapping[str, str]) -> int | None:
    """Where the particle of a declared phrasal verb said at ``n`` stands, after an object
    of a few words ("run *em* off", "run my labels off"), or None. Not when the particle
    opens a "to" of its own ("run it off to Sam": hurried over, an errand's words), nor
    across a pause or a sentence's end, nor when the verb is already followed by it."""
    verb = tokens[n].word
    if tokens[n].possessive or n + 1 >= len(tokens):
        return None
    if f"{verb} {tokens[n + 1].word}" in forms:
        return None  # "run off my labels": already together
    for k in range(n + 1, min(len(tokens), n + 2 + _OBJECT_WORDS)):
        t = tokens[k]
        if t.opens or t.after_pause:
            return None
        if k > n + 1 and t.word in _PARTICLES and f"{verb} {t.word}" in forms:
            after = tokens[k + 1].word if k + 1 < len(tokens) else ""
            return k if after != "to" else None
        if t.word in _OBJECT_ENDS or t.word in _PARTICLES:
            return None
    return None


def _spans(text: str, tokens: Sequence[Token]) -> list[tuple[int, int]]:
    """Where each token stands in ``text`` ((-1, -1): not found as typed)."""
    flat = text.replace("’", "'")
    pos = 0
    out: list[tuple[int, int]] = []
    for t in tokens:
        at = flat.find(t.text, pos)
        if at < 0:
            out.append((-1, -1))
            continue
        out.append((at, at + len(t.text)))
        pos = at + len(t.text)
    return out
