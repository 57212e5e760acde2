"""A colleague who wants the requester's own thing, then the thing handed on: "wang wants my
report, can u send it over", "Zhang needs my file, can you forward it". The thing is the
requester's, so only they may say where it goes, and the sentence that says who wants it is
where they said it: that colleague is whom "it" is sent to, as the reader reads it. Only the
requester's own thing counts ("Wang wants Zhang's file" is a wish about another's thing, which
its owner decides), and only "it"/"them" handed on with no receiver of its own ("send it to
Mo" names Mo; "Rich wants it on the board" wants no thing of the requester's)."""

from __future__ import annotations

from collections.abc import Callable, Sequence

# the wish or need said right after the colleague's name
_WANTS = frozenset({"wants", "needs", "want", "need", "wanted", "needed"})
# the requester's own thing, right after the wish
_OWN = frozenset({"my", "our"})
# the thing handed over, said again
_IT = frozenset({"it", "them"})
# a receiver of its own after "it": "send it to Mo", "forward it on to Mo"
_RECEIVING = frozenset({"to", "for", "with"})


def wants_own_thing(words: Sequence[str], end: int) -> bool:
    """Whether the folded ``words`` right after a name ending at ``end`` say the person
    wants or needs the requester's own thing ("wants my report")."""
    return end + 1 < len(words) and words[end] in _WANTS and words[end + 1] in _OWN


def wishes(words: Sequence[str], end: int) -> bool:
    """Whether the folded ``words`` right after a name ending at ``end`` say the person
    wants or needs anything ("will needs it too"): another who might be meant."""
    return end < len(words) and words[end] in _WANTS


def handed_on(words: Sequence[str], is_give: Callable[[str], bool]) -> bool:
    """Whether the folded ``words`` hand "it"/"them" on with a giving verb and no receiver
    named after it ("send it over", "forward it", not "send it to Mo")."""
    for n in range(len(words) - 1):
        if not (is_give(words[n]) and words[n + 1] in _IT):
            continue
        rest = words[n + 2 : n + 4]
        if not any(w in _RECEIVING for w in rest):
            return True
    return False
