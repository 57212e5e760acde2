"""A facility said as the subject of a statement: "coffee machine's been making a weird noise
all day", "popcorn machine's been beeping for an hour", "the kettle is leaking again". The
facility is named by its name or a synonym of the office's data, with its "'s" for "has"/"is"
read as the tokens write it ("machines"), then a verb of state or of something happening to
it ("been", a past participle, an -ing form, "not"). That is told of the facility (a
complaint, or news): words, never an order for what the facility makes, though its name holds
the product's ("popcorn" of "popcorn machine"). "coffee machine's coffee for me" (a possessive
before a noun) and "coffee machine, make me a latte" (a command) are read as before."""

from __future__ import annotations

from collections.abc import Collection, Sequence

from assistantx.core import language

# what may stand before the facility's name: "the coffee machine's ...", "our kettle is ..."
_BEFORE = frozenset({"the", "our", "that", "this", "my", "ugh", "so", "oh", "welp", "honestly"})
# the helping verbs after the name said in full ("the kettle *is* leaking")
_BE_OR_HAVE = frozenset({"is", "has", "was", "keeps", "kept", "isnt", "hasnt", "wasnt"})
# the words that carry a state after "'s" besides participles and -ing forms
_STATE = frozenset({"been", "not", "never", "always", "still", "just", "gone", "got", "broken"})


def facility_told(w: Sequence[str], facilities: Collection[str]) -> bool:
    """Whether ``w`` (a clause's content words) opens with a facility of ``facilities`` (its
    names and synonyms), then the verb of a statement about it."""
    k = 0
    while k < len(w) and w[k] in _BEFORE:
        k += 1
    for size in (4, 3, 2, 1):
        said = list(w[k : k + size])
        if len(said) < size:
            continue
        after = list(w[k + size : k + size + 2])
        if " ".join(said) in facilities:
            return bool(after) and after[0] in _BE_OR_HAVE and _state(after[1:2])
        contracted = said[-1].endswith("s") and " ".join([*said[:-1], said[-1][:-1]]) in facilities
        if contracted:
            return _state(after[:1])  # "machines been": "machine's been"
    return False


def _state(words: Sequence[str]) -> bool:
    """ "been", "broken", "leaking": a verb of a state or of something under way."""
    if not words:
        return False
    word = words[0]
    if word in _STATE:
        return True
    if word.endswith("ing") and language.verb_lemmas(word):
        return True  # "making", "beeping"
    return language.is_past_participle(word)
