""" "this", "that" or "it" carried somewhere with nothing said that it could be: "can you take
this over to the printer", "take that to Wang". The robot sees nothing held out, and the
words name no thing, so what is carried is asked; it is never guessed from where it goes (a
document because the printer copies, a stamped envelope because the franking machine makes
them, a coffee because the coffee machine does), which moved the wrong thing.

Only where every task word of the message is one of carrying (``give``'s: take, bring,
drop ...), the pronoun is that verb's object, and the message names no item and nobody's
thing ("print my report and take it to Wang": "it" is the report; "take Wang's to him":
Wang's)."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.lexicon import Lexed

_CARRYING = "give"  # the lexicon's kind of the carrying verbs
# a thing described, not named, that "it" may be ("anything I can cut with")
_INDEFINITES = frozenset({"anything", "something", "one", "ones", "any", "some"})
_POINTING = frozenset({"this", "that", "it", "these", "those", "them"})
# what may stand between the verb and its object: whom it is for ("bring me this")
_BETWEEN = frozenset({"self", "word"})
_BETWEEN_WORDS = frozenset({"me", "us", "him", "her", "them", "over", "back", "up"})


def unnamed_carried(whole: Lexed) -> str | None:
    """The question to ask where only a pronoun is carried and nothing names what it is;
    None otherwise. Asked only where the reader would otherwise act (the parser calls it on
    a frame with tasks): a question already asked stays the one asked."""
    mentions = whole.mentions
    cues = [m for m in mentions if m.kind == "cue"]
    if not cues or any(m.ids != (_CARRYING,) for m in cues):
        return None
    for m in mentions:
        if m.kind == "item" or (m.kind in ("person", "self") and m.possessive):
            return None  # "take my report to Wang", "take Wang's to him"
    if any(t.word in _INDEFINITES for t in whole.tokens):
        return None  # "got anything I can trim this with? bring it over": what is found
    for n, m in enumerate(mentions):
        if m.kind != "cue":
            continue
        k = n + 1
        while (
            k < len(mentions)
            and mentions[k].kind in _BETWEEN
            and whole.tokens[mentions[k].start].word in _BETWEEN_WORDS
        ):
            k += 1
        if k < len(mentions) and mentions[k].kind == "pronoun":
            said = whole.tokens[mentions[k].start]
            if said.word in _POINTING:
                verb = whole.tokens[m.start].text
                return (
                    f"What do you want me to {verb.lower()} - what is {said.text!r}? "
                    "Please tell me the thing, and whose it is."
                )
    return None
