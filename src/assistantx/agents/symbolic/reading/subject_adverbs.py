"""An adverb between a named subject and its verb: "Rose *really* needs an umbrella", "Wang
*also* wants a coffee", "Zhang *definitely* has to sign my contract".

Everything that reads a person's role looks at the word right after the name ("Rose needs":
the one in need receives; "Zhang has to sign": the doer; "Wang wants it": a wish about what
was asked). An adverb there says how sure, how badly or how urgently, never who does or gets
what, so it is read away before the lexicon and every later stage sees "Rose needs ...".

Which words are adverbs comes from lemminflect's dictionary, not a list: a word it knows only
as an adverb (or as an adverb and an adjective: "just", "only"). A word that is also a verb or
a noun ("still", "even", "back", "now", "home") is left alone: "Wang still has my stapler" is
said of where the stapler is, and "bring Rose back ..." is no subject at all; only before a
need's verb ("Wang *still* needs a stapler") is any adverb read away, since two finite verbs
never stand in a row. The same test reads the adverbs after a pronoun subject ("she
*definitely* needs one", ``screen.pronoun_subject``). An adverb that
denies the verb ("never", "hardly") is meaning, never read away, and so is a preposition
the dictionary also lists as an adverb ("take the tape from Pat *to* May": May is a name, and
"to" no adverb before the modal "may"). The verb must be a finite
one ("needs", "has", "wanted") or a modal ("must", "will"): a name before a bare verb or a
noun is no subject ("ask Wang nicely to sign" keeps its words).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language

_NEGATIVE = english.words("negative_adverbs") | english.words("statement_negations")
# "take the tape from Pat *to* May": a preposition the dictionary also has as an adverb
_PARTICLES = english.words("prepositions_and_joins")
# "must", "will", "can": a modal takes its subject as a finite verb does ("Zhang really must
# sign"); "need" is listed among the modals for another reader, and is a bare verb here.
_MODALS = english.words("modal_auxiliaries") - {"need", "needs"}
# the verbs of a need, before which any adverb says how or how long, never who
_NEED_LEMMAS = frozenset({"need", "want"})
# the readings that make a word more than an adverb ("still" is a verb, "now" a noun)
_OTHER_READINGS = frozenset({"VERB", "NOUN", "AUX", "PROPN"})


def is_adverb_before_verb(word: str) -> bool:
    """A word the dictionary knows as an adverb, that does not deny and is no preposition:
    an adverb wherever a finite verb follows it right after its subject ("she *still* needs
    a stapler": two finite verbs never stand in a row, so "still" is no verb there)."""
    return "ADV" in language.lemmas(word) and word not in _NEGATIVE and word not in _PARTICLES


def is_plain_adverb(word: str) -> bool:
    """A word the dictionary knows as an adverb and as nothing that could head a clause or a
    noun phrase, and that does not deny ("really", "badly", "also"; not "still", "never")."""
    return is_adverb_before_verb(word) and not set(language.lemmas(word)) & _OTHER_READINGS


def _after_subject(
    words: Sequence[str], is_name: Callable[[str], bool], breaks: Sequence[bool]
) -> set[int]:
    """The places of the adverbs in ``words`` that stand between a person's name and the
    finite verb or modal that follows them; ``breaks[n]`` says a pause or a sentence end comes
    before word ``n`` (an adverb across it belongs to another clause)."""
    drop: set[int] = set()
    for n, w in enumerate(words):
        if not is_name(w):
            continue
        k = n + 1
        # "Rose really badly needs": any run of adverbs within the clause
        while k < len(words) and not breaks[k] and is_adverb_before_verb(words[k]):
            k += 1
        if k == n + 1 or k >= len(words) or breaks[k]:
            continue
        plain = all(is_plain_adverb(w) for w in words[n + 1 : k])
        if (plain and (words[k] in _MODALS or language.is_finite_verb(words[k]))) or (
            _a_need(words[k])
        ):
            drop.update(range(n + 1, k))
    return drop


def _a_need(word: str) -> bool:
    """A need's finite verb ("needs", "wants"): "Wang *still* needs a stapler" says the need
    goes on, never where the stapler is ("Wang still has my stapler" keeps its "still")."""
    return language.is_finite_verb(word) and bool(language.verb_lemmas(word) & _NEED_LEMMAS)


def read_subject_adverbs(tokens: Sequence[Token], is_name: Callable[[str], bool]) -> list[Token]:
    """``tokens`` without the adverbs between a person's name (not possessive: "Wang's really
    ...") and its verb."""
    words = [t.word if not t.possessive else "" for t in tokens]
    breaks = [t.after_pause or t.opens or t.possessive for t in tokens]
    drop = _after_subject(words, lambda w: bool(w) and is_name(w), breaks)
    return [t for n, t in enumerate(tokens) if n not in drop]


def without_subject_adverbs(words: Sequence[str], is_name: Callable[[str], bool]) -> list[str]:
    """A piece's folded words without those adverbs (the speech acts read the words)."""
    drop = _after_subject(words, is_name, [False] * len(words))
    return [w for n, w in enumerate(words) if n not in drop]
