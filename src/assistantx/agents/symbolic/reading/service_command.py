"""A service asked for in the imperative: "fax the booking confirmation to the agent",
"laminate the meeting notes", "shred these". A service's verb in its bare form heading a
piece, followed by what opens its object (an article, a possessive, a pointer or an object
pronoun), is a command whatever that object is: a bare singular noun never opens a subject
with "the" or "my" after it ("fax the ..." has no reading as "the fax ..."), so the piece is
no statement even when its object's words look like a clause ("the *booking* confirmation",
"the *meeting* notes" read as a progressive). The verbs are those of English's services
(``english.yaml``'s ``service_verbs``), those of the standard services any office may lack
(``standard_services.yaml``) and the office's own: the request is read as one, and a service
the office does not offer is declined by the screen (``screen.service``), never noted."""

from __future__ import annotations

import functools
from collections.abc import Collection

from assistantx.core import english
from assistantx.core.office_upgrade import standard

# What opens a verb's object right after it: "the", "my", "these", "it", "them" ...
_OBJECT_OPENERS = english.words("screen_determiners") - {"me"}
# Words said before the command that do not change it ("please fax ...", "just shred ...").
_OPENERS = frozenset({"please", "pls", "plz", "kindly", "just", "also", "then", "and", "so"})


@functools.cache
def english_service_verbs() -> frozenset[str]:
    """The verbs of the services people ask an office for, whether this office offers them
    or not: English's list and the standard services' verbs."""
    standard_verbs = (
        str(verb).lower()
        for op in standard()["operations"].values()
        for verb in op.get("verbs") or []
        if len(str(verb).split()) == 1
    )
    return english.words("service_verbs") | frozenset(standard_verbs)


def service_command(w: list[str], office_verbs: Collection[str] = ()) -> bool:
    """Whether the content words ``w`` open with a service's verb in its bare form and then
    an object's opener ("fax the ...", "scan my ...", "laminate these"); ``office_verbs``:
    the office's own service verbs, read the same."""
    k = 0
    while k < len(w) and w[k] in _OPENERS:
        k += 1
    if k + 1 >= len(w):
        return False
    verb, nxt = w[k], w[k + 1]
    if verb not in english_service_verbs() and verb not in office_verbs:
        return False
    # the lists hold bare forms only: "faxed the contract yesterday" is a past act, left to
    # the statement's rules
    return nxt in _OBJECT_OPENERS
