"""After the frames: a request the frames could not read that asks for a thing no one in
this office has ("bring me a tape measure") is declined in words, with what the office offers,
rather than asked about again."""

from __future__ import annotations

import re
from collections.abc import Sequence

from assistantx.agents.symbolic.reading._objects import REASON_CONJUNCTIONS, modifiers
from assistantx.agents.symbolic.reading.categories import (
    Category,
    category_for_purpose,
    category_named,
    office_choices,
    which_question,
)
from assistantx.agents.symbolic.reading.head_names import shared_types
from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language
from assistantx.core.wording import a_thing

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
    if thing in terms.lex.items:
        return None  # the office's own thing, misread around it: ask, never deny it exists
    several = _several(thing)
    return (
        f"Sorry, there {'are' if several else 'is'} no {thing} in this office that I know of, "
        f"so I can't get you {'any' if several else 'one'}. {terms.capabilities()}"
    )


def _several(thing: str) -> bool:
    """Whether an unknown thing's name is a plural: the dictionary's ("biscuits"), or a word
    it does not know ending as plurals do ("paperclips", not "class")."""
    last = thing.split()[-1]
    if language.is_plural_noun(thing):
        return True
    return not language.lemmas(last) and last.endswith("s") and not last.endswith("ss")


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
    thing = terms.unknown_thing(words)
    category = _category(thing, words)
    choices = office_choices(terms.office, category) if category is not None else []
    if category is None:
        near = near_items(terms, thing)  # "a whiteboard pen": board pen or whiteboard marker?
        choices = near if len(near) > 1 else []
    if not choices:  # "a roller": the paint roller or the lint roller? (``head_names``)
        shared = shared_types(terms.lex.shared_heads, thing)
        choices = [terms.office.item_type(t).name for t in shared]
    return which_question(choices) if choices else None


def near_items(terms: Terms, thing: str) -> list[str]:
    """The names of the office's things that a name of several words asked for, no name of
    the office itself, nearly says ("a whiteboard pen" where the whiteboard marker is also
    called a board pen): a name of one of them (or a synonym) with the same head noun and
    another word the same, or all but one of its words the same, each word the same as
    typed, a compound's end ("whiteboard", "board") or within a typo."""
    said = thing.split()
    if len(said) < 2 or said[-1] in _BACK_WORDS:
        return []
    out: list[str] = []
    for t in terms.office.item_types:
        for name in (t.name, *t.synonyms):
            words = language.fold(name).lower().split()
            if words == said:
                return []  # the office's own name: nothing near to offer
            matched = sum(any(_same_word(w, v) for v in words) for w in said)
            head = _same_word(said[-1], words[-1])
            if (head and matched >= 2) or (len(words) >= 2 and matched >= len(said) - 1 >= 2):
                out.append(t.name)
                break
    return list(dict.fromkeys(out))


def _same_word(typed: str, word: str) -> bool:
    """A word of a name said as typed, as the end of a compound ("whiteboard" for "board")
    or within a typo of it."""
    if typed == word:
        return True
    shorter, longer = sorted((typed, word), key=len)
    if len(shorter) >= 4 and longer.endswith(shorter):
        return True
    return bool(language.closest(typed, [word]))


def _said_as_typed(tokens: Sequence[Token], thing: str) -> tuple[str, ...]:
    """The words of ``thing`` as the requester typed them (before any typo was mended), so
    the request can have them replaced."""
    said = thing.split()
    words = [t.word for t in tokens]
    for k in range(len(words) - len(said) + 1):
        if words[k : k + len(said)] == said:
            return tuple(language.fold(t.text).lower() for t in tokens[k : k + len(said)])
    return tuple(said)


def one_choice(
    terms: Terms, tokens: Sequence[Token], mentions: Sequence[Mention]
) -> tuple[str, tuple[str, ...]] | None:
    """The office's one thing of the category asked for ("something to write with" where
    the only such thing is a pen), by its item type's name, with the words that said the
    category; None where the office has none or several of it, or names its one only by a
    synonym ("soda from the vending machine")."""
    words = _asked_words(tokens, mentions)
    if words is None:
        return None
    thing = terms.unknown_thing(words)
    category, said = _category_said(thing, words)
    if category is None:
        near = near_items(terms, thing)
        if len(near) != 1:
            return None
        return near[0], _said_as_typed(tokens, thing)
    choices = office_choices(terms.office, category)
    names = {t.name for t in terms.office.item_types}
    if len(choices) != 1 or choices[0] not in names:
        return None
    return choices[0], said


# How the one thing of a category is offered where it is someone's own kind of thing.
PROPOSED = "I can get you "


def proposal(choice: str) -> str:
    """ "I can get you a pen. Would you like that?": the one thing, offered plainly."""
    return f"{PROPOSED}{a_thing(choice)}. Would you like that?"


def with_choice(text: str, said: Sequence[str], choice: str) -> str | None:
    """``text`` with the words that said the category (as folded words, any punctuation
    between) replaced by the one thing ("bring me something to write with" → "bring me a
    pen"); None when they are not found in it."""
    if not said:
        return None
    pattern = r"\b" + r"\W+".join(re.escape(w) for w in said) + r"\b"
    found = re.search(pattern, language.fold(text), flags=re.IGNORECASE)
    if found is None or len(language.fold(text)) != len(text):
        return None
    start, end = found.span()
    before = text[:start].rstrip().lower()
    if before.endswith((" a", " an", " some", " any")) or before in ("a", "an", "some", "any"):
        return f"{text[:start]}{choice}{text[end:]}"  # "a drink" → "a coffee"
    return f"{text[:start]}{a_thing(choice)}{text[end:]}"


def _category(thing: str, words: list[str]) -> Category | None:
    """The category of "a drink", "some hot drinks", or of "something to write with"."""
    return _category_said(thing, words)[0]


def _category_said(thing: str, words: list[str]) -> tuple[Category | None, tuple[str, ...]]:
    """The category and the words that said it: "drink" in "a drink", "something to write
    with"."""
    found = category_named(thing) if thing else None
    if found is not None:
        return found, tuple(thing.split())
    for n, w in enumerate(words[:-2]):
        if w in _SOMETHING and words[n + 1] == "to":
            category = category_named(" ".join(words[n : n + 3])) or category_for_purpose(
                words[n + 2]
            )
            end = n + 4 if words[n + 3 : n + 4] == ["with"] else n + 3
            return category, tuple(words[n:end])
    return None, ()


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
