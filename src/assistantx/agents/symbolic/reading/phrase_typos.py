"""A typo in one word of a thing's name of several words: "blu tac" for the office's blu tack,
"gaffa tap" for its gaffa tape. Each word is corrected on its own against the office's words
(``Lexicon._correct``), which leaves a short word ("tac", under four letters) and an English
word ("tap") as typed, so the name was never found. Here the office's own names of several
words are compared as phrases: where all their words but one are said exactly, in a row, and
the one left is a single slip from the name's word, that word is the name's.

The slip is a letter left out or added, or two neighbours swapped ("tac", "tap", "blue"). A
letter changed for another makes another English word as often as not ("paper cut" beside a
paper cup), so it is taken for a slip only beside a word English rarely uses ("gaffa tapr").
A word that is itself one of the office's words is never changed, nor one of English's most
common words ("for" after "order" is no slip of an "order form": read so, "sign my purchase
order for the new rollers" lost its "for" to the office's "form" and asked what to do with the
rollers), and a typo as near to the words of two names is left alone."""

from __future__ import annotations

from collections.abc import Callable, Collection, Sequence

from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language

# the shortest typed word taken for a slip in a name's word ("tac", "tap")
_SHORTEST = 3
# the everyday words ("for", "from", "back") that are never a slip in a name's word
_COMMON = english.words("common")


class PhraseTypos:
    """The office's names of several words, indexed by each word and its place in the name,
    so that a message is compared only with the names one of whose words it says where that
    word stands (the lexicon reads every rewrite of a message: comparing each token with every
    name cost more than the rest of the reading together)."""

    def __init__(self, names: Collection[str], known: Callable[[str], bool]) -> None:
        phrases = {tuple(n.split()) for n in names if " " in n}
        # a word of any of the names is that word ("bubble wrap" beside "bubble wraps"), never
        # a slip in another's
        self._said_right = frozenset(w for n in names for w in n.split())
        self._known = known
        self._at: dict[tuple[int, str], list[tuple[str, ...]]] = {}
        for words in sorted(phrases):
            for k, word in enumerate(words):
                self._at.setdefault((k, word), []).append(words)
        self._longest = max((len(p) for p in phrases), default=0)

    def _typo(self, word: str) -> bool:
        return word not in self._said_right and not self._known(word) and word not in _COMMON

    def read(self, tokens: Sequence[Token]) -> list[Token]:
        """``tokens`` with the one mistyped word of a name of several words read as the
        name's word."""
        out = list(tokens)
        if not self._at:
            return out
        for i in range(len(out)):
            # a name with one word mistyped says all its others where they stand
            candidates = {
                words
                for k in range(min(self._longest, len(out) - i))
                for words in self._at.get((k, out[i + k].word), ())
            }
            meant = {
                (i + j, words[j])
                for words in candidates
                if (j := _one_slip(out, i, words, self._typo)) is not None
            }
            if len(meant) == 1:  # two names' words as near: left as typed
                ((at, word),) = meant
                out[at] = out[at].corrected_to(word)
        return out


def _one_slip(
    tokens: Sequence[Token], i: int, words: tuple[str, ...], typo: Callable[[str], bool]
) -> int | None:
    """Where in ``words`` the one word typed with a slip stands, when the tokens from ``i``
    say all the others exactly, in one phrase (no pause or sentence end inside it);
    ``typo``: whether a word may be a slip at all."""
    said = tokens[i : i + len(words)]
    if len(said) != len(words) or any(t.opens or t.after_pause for t in said[1:]):
        return None
    differ = [j for j, (t, w) in enumerate(zip(said, words, strict=True)) if t.word != w]
    if len(differ) != 1:
        return None
    j = differ[0]
    typed = said[j].word
    if len(typed) < _SHORTEST or not typed.isalpha() or not typo(typed):
        return None
    if said[j].possessive and j != len(words) - 1:
        return None  # "gaffa's tape": whose, not a slip
    if _dropped_or_swapped(typed, words[j]):
        return j
    if not language.within(typed, [words[j]], 1):
        return None
    rare = [w for w in (typed, *(t.word for t in said)) if language.zipf(w) < language.COMMON_ZIPF]
    return j if rare else None


def _dropped_or_swapped(typed: str, word: str) -> bool:
    """Whether ``typed`` is ``word`` with one letter left out or added, or two neighbours
    swapped: a slip of the hand, never a letter changed ("cut" for "cup" is another word)."""
    from rapidfuzz.distance import Indel  # as ``language`` does: on the first use

    if Indel.distance(typed, word, score_cutoff=1) <= 1:
        return True
    return sorted(typed) == sorted(word) and bool(language.within(typed, [word], 1))
