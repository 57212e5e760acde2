"""Clauses that open a request of their own on a word the lexicon has no cue for: a person
asked to do a person's work ("... and ask Dov to sign my call sheet", "... and tell her to
stamp it", "... and have the Boss sign my form": the clause opens on the verb of asking; "...,
and can Mark sign my form": on the modal of a question put to them, the bare verb after), and
a thing handed across with an everyday verb ("..., and then pop a rush tag over to me"). Read
as words that run on from the clause before, they dropped a signature or left the thing
unexplained."""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.obligation import obliged_verb
from assistantx.agents.symbolic.reading.tokens import Token, prev_word
from assistantx.core import english, language

# The verbs that ask a person to do something ("ask Dov to ...", "tell her to ...").
_ASKING = frozenset({"ask", "tell", "have", "let"})
# The modals that ask a colleague for work in a question ("can Mark sign ...", "could you").
_ASKING_MODALS = frozenset({"can", "could", "would", "will"})
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
    if work.kind != "cue" or verb not in _ASKING | _ASKING_MODALS:
        return False
    if verb in _ASKING_MODALS:
        # "..., and can Mark sign my form": a question asked of a colleague's work, the bare
        # verb right after them, is a request of its own as "ask Mark to sign" is
        said = work.start == who.end
    elif tokens[who.end].word == "to":
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


def obliged_to_go(mentions: Sequence[Mention], n: int, tokens: Sequence[Token]) -> bool:
    """Whether mention ``n`` opens a thing said to have to go somewhere ("..., and my torch
    needs to go to Ida", "and the stapler should go back to Wang"): a delivery of its own,
    never whom the clause before is for ("I need a coffee, and my torch needs to go to Ida":
    the coffee stays the speaker's)."""
    k = n
    if k < len(mentions) and mentions[k].kind in ("self", "person") and k + 1 < len(mentions):
        k += 1  # "my torch", "Ida's torch"
    if k >= len(mentions) or mentions[k].kind != "item":
        return False
    words = [t.word for t in tokens[mentions[k].end : mentions[k].end + 6]]
    verb = obliged_verb(words, 0)
    return verb is not None and words[verb] == "go"


# The verbs that have work done on a thing ("have my letter digitised", "get it signed").
_DONE_ON = english.words("done_on_verbs")
# The cues that hand or make a thing rather than work on it ("... and my notes sent too").
_NOT_WORK = frozenset({"give", "make", "send"})


def has_it_done(mentions: Sequence[Mention], n: int, tokens: Sequence[Token]) -> bool:
    """Whether mention ``n`` opens a thing to have worked on, after another request ("forward
    my slides to Bo and have my letter digitised", "... and get my contract signed by Lee",
    "... and my report printed"): "have"/"get", the owner's word, the item and right after it
    the participle of a work's verb. Read as words that ran on from the clause before, the
    second piece of work was silently dropped. Without "have"/"get" the owner must be said
    ("my report printed"), so "send my notes to Bo and the report too" keeps its reading."""
    k = n
    causative = (
        k < len(mentions)
        and mentions[k].kind == "word"
        and tokens[mentions[k].start].word in _DONE_ON
    )
    if causative:
        k += 1
    owned = k < len(mentions) and mentions[k].kind in ("self", "person") and mentions[k].possessive
    if owned:
        k += 1
    if not (causative or owned) or k + 1 >= len(mentions):
        return False
    thing, work = mentions[k], mentions[k + 1]
    return (
        thing.kind == "item"
        and work.kind == "cue"
        and work.start == thing.end
        and not set(work.ids) & _NOT_WORK
        and language.is_past_participle(tokens[work.start].word)
    )
