"""An outsider named bare, as family and callers are ("Dad at reception says his son's lost
his tie", "Mum on the phone said her pen ran out", "courier reckons his van's blocked in"),
reporting something: a statement, context for the request said after it.

A person named by what they are (``outsider_nouns``: dad, mum, courier, visitor ...) opens
the clause with no article, perhaps where they are ("at reception", "on the phone": a few
words), then a verb of saying. What follows is their report: its pronouns are theirs and bind
inside it, never to a colleague. A clause that says "you" ("Dad says could you bring him a
tie") relays a request and is read as one; a colleague's name or alias ("Wang says his
stapler is broken") is no outsider and is read as before."""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.outsider_need import is_outsider_noun

# the verbs a report is said with
_SAYING = frozenset(
    {"says", "said", "asks", "asked", "reckons", "reckoned", "tells", "told", "mentioned"}
    | {"thinks", "thought", "claims", "claimed", "reports", "reported"}
)
# at most this many words between the outsider and the verb: "at the front door"
_MOST_PLACE_WORDS = 4
# words that put a request to the assistant inside the report
_ADDRESSED = frozenset({"you", "u", "ya", "please", "pls", "plz"})


def outsider_reports(w: Sequence[str]) -> bool:
    """Whether the words ``w`` of a clause open with an outsider named bare who reports
    something (see the module's note). The caller rules out the office's own names."""
    if not w or not is_outsider_noun(w[0]):
        return False
    if set(w) & _ADDRESSED:
        return False
    said = next((n for n, x in enumerate(w[1 : _MOST_PLACE_WORDS + 2], 1) if x in _SAYING), None)
    return said is not None and said + 1 < len(w)
