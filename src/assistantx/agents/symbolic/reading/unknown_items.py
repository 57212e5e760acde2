"""After the frames: a request the frames could not read that asks for a thing no one in
this office has ("bring me a tape measure") is declined in words, with what the office offers,
rather than asked about again."""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading._objects import REASON_CONJUNCTIONS, modifiers
from assistantx.agents.symbolic.reading.categories import (
    Category,
    category_for_purpose,
    category_named,
    office_choices,
    which_question,
)
from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language

# The words of the phrases that point back to an item named before ("another", "a few more").
_BACK_WORDS = english.words("another_one")
# Words that end the name of a thing asked for: a reason, a courtesy ("a dispatcher please").
_THING_ENDS = REASON_CONJUNCTIONS | english.words("polite") | {"as"}
_SOMETHING = frozenset({"something", "anything", "smth", "sth"})


def unknown_item(terms: Terms, tokens: Sequence[Token], mentions: Sequence[Mention]) -> str | None:
    """ "bring me a tape measure": a fetch of a thing no one here has, said in words."""
    words = _asked_words(tokens, mentions)
    if words is None:
        return None
    thing = terms.unknown_thing(words)
    if thing and set(thing.split()) <= _BACK_WORDS:
        return None  # "bring me a few": how many of something not named, so ask what
    if not thing or not all(language.lemmas(w) or language.zipf(w) > 0 for w in thing.split()):
        return None
    return (
        f"Sorry, there is no {thing} in this office that I know of, so I can't get you "
        f"one. {terms.capabilities()}"
    )


def category_asked(
    terms: Terms, tokens: Sequence[Token], mentions: Sequence[Mention]
) -> str | None:
    """ "bring me a drink", "get me something to write with": a fetch of a category word
    (``categories``) where the office has things of that category but none so called: the
    question which of them ("Which would you like: tea or hot chocolate?"). None: no
    category, or the office has nothing of it (then it is declined as an unknown thing)."""
    words = _asked_words(tokens, mentions)
    if words is None:
        return None
    category = _category(terms.unknown_thing(words), words)
    choices = office_choices(terms.office, category) if category is not None else []
    return which_question(choices) if choices else None


def _category(thing: str, words: list[str]) -> Category | None:
    """The category of "a drink", "some hot drinks", or of "something to write with"."""
    found = category_named(thing) if thing else None
    if found is not None:
        return found
    for n, w in enumerate(words[:-2]):
        if w in _SOMETHING and words[n + 1] == "to":
            return category_named(" ".join(words[n : n + 3])) or category_for_purpose(words[n + 2])
    return None


def _asked_words(tokens: Sequence[Token], mentions: Sequence[Mention]) -> list[str] | None:
    """The words after a fetch's or a making's verb that name what is asked for, when the
    request names no item of the office (None: it does, or there is no such verb)."""
    cue = next((m for m in mentions if m.kind == "cue" and set(m.ids) & {"give", "make"}), None)
    context = modifiers(tokens, mentions)  # "... because my headlamp is dying"
    if cue is None or any(m.kind == "item" and m.start not in context for m in mentions):
        return None
    if any(m.kind == "facility" for m in mentions):
        return None
    words = [t.word for t in tokens[cue.end :]]
    # the thing ends where a reason starts: "a power bank as my headlamp is dying"
    ends = [n for n, w in enumerate(words) if w in _THING_ENDS]
    return words[: ends[0]] if ends else words
