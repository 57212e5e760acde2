"""Two readings of a carrying errand across the office, made on the readings stage.

A verb of hurrying that leads a carrying idiom ("run it over to them", "nip my proof across
to Will", "pop it round to standards") asks the assistant to carry the thing there itself:
the particle of going across the office before the "to" says so. Such a verb is a plain word
then, never the request for a service that happens to list it among its verbs (a courier
whose verbs include "run"), so nothing is sent out of the office on a hurrying verb.

"them" after "to", with no colleague named before it and exactly one facility of the office
named before it ("standards need to see my proof ... run it over to *them*"), is that
facility: a desk or team named as a plural subject is whom "them" points back at.
"""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language

# Verbs that lead another action or an errand ("go print it", "pop it over to Will").
_HURRYING = english.words("serial_verbs")
# Particles of going across the office before an errand's "to" ("over to", "across to").
_ACROSS = english.words("errand_particles")
_OBJECT_WORDS = 5  # at most this many words of the verb's object before the particle
_CLAUSE_ENDS = frozenset(".!?;,\n")
# Plural pronouns that may point back at a team or desk.
_PLURAL_OBJECTS = frozenset({"them"})


def errand_verbs(
    tokens: Sequence[Token], gaps: Sequence[str], mentions: Sequence[Mention]
) -> tuple[list[Mention], frozenset[int]]:
    """``mentions`` with every hurrying verb that leads a carrying idiom read as a plain
    word, and the token indices of those verbs (never a send-out service's verb)."""
    out = list(mentions)
    verbs: set[int] = set()
    for n, m in enumerate(out):
        if m.kind != "cue" or m.end - m.start != 1:
            continue
        if not language.verb_lemmas(tokens[m.start].word) & _HURRYING:
            continue
        if _carried_across(tokens, gaps, m.end):
            out[n] = Mention("word", m.start, m.end, (tokens[m.start].word,), False, m.text)
            verbs.add(m.start)
    return out, frozenset(verbs)


def _carried_across(tokens: Sequence[Token], gaps: Sequence[str], after: int) -> bool:
    """Whether a particle of going across, then "to", follows the verb's object in its own
    clause ("run [my page proof] over to ...")."""
    for k in range(after, min(len(tokens) - 1, after + _OBJECT_WORDS + 1)):
        if k > after and any(c in _CLAUSE_ENDS for c in gaps[k]):
            return False
        if tokens[k].word in _ACROSS and tokens[k + 1].word == "to":
            return not any(c in _CLAUSE_ENDS for c in gaps[k + 1])
    return False


def facility_pronouns(tokens: Sequence[Token], mentions: Sequence[Mention]) -> list[Mention]:
    """``mentions`` with a "to them" read as the one facility named before it, where no
    colleague was named before it; otherwise unchanged (asked about as before)."""
    out = list(mentions)
    for n, m in enumerate(out):
        if m.kind != "pronoun" or tokens[m.start].word not in _PLURAL_OBJECTS:
            continue
        if m.start == 0 or tokens[m.start - 1].word != "to":
            continue
        before = out[:n]
        if any(b.kind == "person" for b in before):
            continue  # "them" may be people named before: asked, never guessed
        facilities = {b.ids for b in before if b.kind == "facility"}
        if len(facilities) != 1:
            continue
        (ids,) = facilities
        out[n] = Mention("facility", m.start, m.end, ids, False, m.text)
    return out
