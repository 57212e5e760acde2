"""The speaker declines more of a thing: "no more water for me thanks", "no coffee for me
today", "no more tea for us". "no" before a quantity of a thing said by itself (at most
"more", then the thing, then only whom and when it is for) negates the quantity: the speaker
wants none, so nothing is offered and nothing is made or moved. Before, "no more water for
me thanks" made water, a wrong physical action. A "no" that only says how a thing is taken
("no milk in my coffee please") goes on to the thing asked for, and "one more coffee for me"
or "more coffee please" asks, read as before."""

from __future__ import annotations

import itertools
from collections.abc import Container

from assistantx.core import language

# "no more", "no further", "no extra": the word of quantity "no" may carry before the thing
_MORE = frozenset({"more", "further", "extra", "additional", "other"})
# what may follow the thing and still end the clause: whom and when it is for, politeness,
# and the words that stress the refusal ("no more coffee for me today thanks")
_TAIL = frozenset(
    {
        "for",
        "me",
        "us",
        "today",
        "tonight",
        "now",
        "anymore",
        "any",
        "again",
        "please",
        "pls",
        "thanks",
        "thank",
        "you",
        "thx",
        "ta",
        "cheers",
        "though",
        "either",
        "ever",
        "just",
        "yet",
        "this",
        "week",
        "afternoon",
        "morning",
        "evening",
        "i",
        "think",
        "im",
        "good",
        "fine",
        "ok",
        "okay",
        # "no pen needed, thanks": the thing said not to be wanted at all
        "needed",
        "required",
        "necessary",
        "wanted",
    }
)


def declines_more(w: list[str], items: Container[str]) -> bool:
    """Whether ``w`` (a piece's content words) is "no [more] <a thing of ``items``>", then
    only the words of ``_TAIL`` (or "no more <a noun>", "no <a noun> for me" and those)."""
    if len(w) < 2 or w[0] != "no":
        return False
    more = w[1] in _MORE
    at = 2 if more else 1
    size = next((k for k in (3, 2, 1) if " ".join(w[at : at + k]) in items), 0)
    if size:
        return all(x in _TAIL for x in w[at + size :])
    # a thing the office does not list ("no more tea for me" where nobody makes tea): a
    # noun, then the tail; "more" or the speaker named says it is a quantity of it declined,
    # never "no rush", "no worries" (no quantity, nobody's)
    end = at
    while end < len(w) and end - at < 3 and w[end] not in _TAIL and language.is_noun(w[end]):
        end += 1
    tail = w[end:]
    mine = any(a == "for" and b in ("me", "us") for a, b in itertools.pairwise(tail))
    return end > at and (more or mine) and all(x in _TAIL for x in tail)
