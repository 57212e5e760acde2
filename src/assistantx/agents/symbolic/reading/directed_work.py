"""Clauses that open a request of their own on a word the lexicon has no cue for: a person
asked to do a person's work ("... and ask Dov to sign my call sheet", "... and tell her to
stamp it", "... and have the Boss sign my form": the clause opens on the verb of asking), and
a thing handed across with an everyday verb ("..., and then pop a rush tag over to me"). Read
as words that run on from the clause before, they dropped a signature or left the thing
unexplained."""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.tokens import Token, prev_word
from assistantx.core import english, language

# The verbs that ask a person to do something ("ask Dov to ...", "tell her to ...").
_ASKING = frozenset({"ask", "tell", "have", "let"})
_BACK_REFERENCES = frozenset({"it", "them", "this", "that", "these", "those"})
# The verbs of asking followed by the bare verb of the work ("have the Boss sign my form").
_BARE = english.words("doer_verbs_bare")


def asks_someone_to_work(mentions: Sequence[Mention], n: int, tokens: Sequence[Token]) -> bool:
    """Whether mention ``n`` opens "ask Dov to sign" (the verb of asking, or the person or
    pronoun after it): a person asked to do the work named right after their "to"."""
    if (
        n < len(mentions)
        and mentions[n].kind == "word"
        and tokens[mentions[n].start].word in _ASKING
    ):
        n += 1  # the lexicon keeps the verb of asking as a plain word
    rest = [m for m in mentions[n : n + 3] if not (m.kind == "word" and m.text.lower() == "to")]
    if len(rest) < 2:
        return False
    who, work = rest[0], rest[1]
    if who.kind not in ("person", "pronoun") or who.end >= len(tokens):
        return False
    verb = prev_word(tokens, who.start)
    if verb not in _ASKING or work.kind != "cue":
        return False
    if tokens[who.end].word == "to":
        said = work.start == who.end + 1  # "ask Dov to sign"
    else:
        said = verb in _BARE and work.start == who.end  # "have the Boss sign"
    # "bring Dov my form and ask him to sign it": the form brought is the one signed, one
    # errand as before; the clause is a request of its own when it names its item
    return said and (work.end >= len(tokens) or tokens[work.end].word not in _BACK_REFERENCES)


# The particles of handing a thing across ("pop it *over* to me", "bung one *round* to Dov").
_ACROSS = frozenset({"over", "round", "across"})


def hands_across(mentions: Sequence[Mention], n: int, tokens: Sequence[Token]) -> bool:
    """Whether mention ``n`` opens a handing said with an everyday verb the lexicon has no cue
    for ("... and then pop a rush tag over to me"): a verb, the thing, then "over/round/
    across to" someone; a request of its own, never words that run on from the clause
    before."""
    if n + 1 >= len(mentions) or mentions[n].kind != "word":
        return False
    verb, thing = mentions[n], mentions[n + 1]
    after = [t.word for t in tokens[thing.end : thing.end + 2]]
    return (
        bool(language.verb_lemmas(tokens[verb.start].word))
        and thing.kind == "item"
        and after[:1] != []
        and after[0] in _ACROSS
        and after[1:] == ["to"]
    )
