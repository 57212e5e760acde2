"""The speaker's own lack of a thing, said to the assistant: "I've run out of wipes", "I'm out
of paper", "I have no pen", "no pens left". Said to an assistant that fetches things, the
lack is a want of the thing for the speaker, not news: the clause is no statement (the
speech acts read it as they read "out of pens"), so the thing is asked for as any want of
the speaker's is (the consent rules for another's item still apply). The phrases are the
language data's (``speaker_lack_phrases``, ``speaker_lack_tails``). A lack said of home or
beside the speaker's own plan to get more stays words (``screen.statement.own_lack``, read
whatever the speech acts say), and a colleague's lack ("Wang has no pen") or a facility's
("the printer has run out of paper") opens with no first person: read as before."""

from __future__ import annotations

from collections.abc import Callable, Sequence

from assistantx.agents.symbolic.reading.lexicon import Lexicon
from assistantx.core import english

_PHRASES = tuple(tuple(p.split()) for p in english.entries("speaker_lack_phrases"))
# the kinds of thing the office can give the speaker: a belonging someone has or a supply, and
# what a machine makes; one's own lunch, paper or file is nobody's to bring ("I have no lunch
# today" is news)
_GIVEN = frozenset({"belonging", "product"})
_TAILS = tuple(tuple(p.split()) for p in english.entries("speaker_lack_tails"))
# the words between the lack and its thing ("out of *any* paper", "no *more* pens")
_BEFORE_THING = frozenset({"a", "an", "any", "the", "my", "our", "some", "more", "clean", "spare"})


def speaker_lacks(w: Sequence[str], names_item: Callable[[list[str]], bool]) -> bool:
    """Whether ``w`` (a clause's content words) opens with the speaker's lack of a thing
    that ``names_item`` knows: a lack phrase, then the thing ("I've run out of wipes and
    ..."), or "no", the thing, then a word of the lack's tail ("no pens left")."""
    if any(
        tuple(w[: len(phrase)]) == phrase and _thing_at(w, len(phrase), names_item) is not None
        for phrase in _PHRASES
    ):
        return True
    if w[:1] != ["no"]:
        return False
    end = _thing_at(w, 1, names_item)
    return end is not None and any(tuple(w[end : end + len(t)]) == t for t in _TAILS)


def _thing_at(w: Sequence[str], k: int, names_item: Callable[[list[str]], bool]) -> int | None:
    """Where the thing said from ``k`` ends (past its article), if the office knows it."""
    while k < len(w) and w[k] in _BEFORE_THING:
        k += 1
    for size in (3, 2, 1):
        if k + size <= len(w) and names_item(list(w[k : k + size])):
            return k + size
    return None


def given_thing(lex: Lexicon) -> Callable[[list[str]], bool]:
    """Whether words name an item of ``lex``'s office of a kind the office can give."""

    def given(said: list[str]) -> bool:
        type_id = lex.items.get(" ".join(said))
        return type_id is not None and lex.office.item_type(type_id).kind in _GIVEN

    return given
