"""Work reported done, in the present-perfect passive: "they've just been sharpened", "it has
already been signed", "the blades have been honed", "it's been laminated".

"has/have been <participle>" tells that the work was done to the thing, and is done now: it
is no request for that work, however much the participle is an office service's own verb. It
is a reason beside a wish ("nobody touch my clippers, they've just been sharpened": keep away
from them *because* they are fresh), never the work asked. Read as a request, the office ran
the service again on a thing the speaker had just got back and wanted left alone.

Only the clause's own statement counts: its subject comes first (a pronoun with its
contracted "'ve"/"'s", or a noun phrase with no verb in it), then the auxiliary, then at most
a few adverbs ("just", "already"), then "been" and a past participle. The auxiliary first is
a question ("has my report been bound yet?", answered in words); a relative clause after a
request ("bring me the folder that's been signed") has a verb before it and is left to the
request; and a request after it in the same piece ("..., so could you bring it") keeps the
piece a request.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

from assistantx.core import language

# the perfect's "have" spelled out or contracted apart ("the clippers 've been", "it 's
# been"), and a pronoun with it contracted as the tokenizer joins them ("theyve", "its")
_PERFECT = frozenset({"has", "have", "ve", "s"})
_PRONOUN_PERFECT = frozenset({"ive", "weve", "youve", "theyve", "its", "hes", "shes", "thats"})
# adverbs of the done work between "have" and "been" ("has *just* been", "'ve *all* been")
_BETWEEN = frozenset({"just", "already", "now", "all", "both", "recently", "finally", "also"})
# words that make the piece ask, wherever they stand ("could you", "please", "so bring")
_ASKING = frozenset({"you", "u", "please", "pls", "plz", "can", "could", "would", "will"})
# how far the auxiliary may stand from the clause's start: "the two blades of my clippers"
_SUBJECT_REACH = 6


def reports_done_work(w: Sequence[str], verb_words: Callable[[str], bool]) -> bool:
    """Whether the content words ``w`` of a piece are a present-perfect passive told of a
    thing: a subject, "has/have [just] been <participle>", and nothing asked. ``verb_words``:
    whether a word before the auxiliary is a verb the speaker could be asking with ("bring",
    "print"), which makes the clause a relative one inside a request."""
    if set(w) & _ASKING:
        return False
    for n in range(min(len(w), _SUBJECT_REACH + 1)):
        if w[n] in _PRONOUN_PERFECT:
            perfect = n == 0  # "theyve been ...": its own subject, first in the clause
        elif w[n] in _PERFECT:
            perfect = n > 0  # "has my report been": the auxiliary first asks
        else:
            continue
        if not perfect or any(verb_words(x) for x in w[:n]):
            return False
        return _been_participle(w[n + 1 :])
    return False


def _been_participle(rest: Sequence[str]) -> bool:
    k = 0
    while k < len(rest) and rest[k] in _BETWEEN:
        k += 1
    if k >= len(rest) or rest[k] != "been":
        return False
    # the participle itself, or after one word of a hyphenated prefix ("been heat sealed")
    return any(language.is_past_participle(x) for x in rest[k + 1 : k + 3])
