"""A colleague who wants the requester's own thing, then the thing handed on: "wang wants my
report, can u send it over", "Zhang needs my file, can you forward it". The thing is the
requester's, so only they may say where it goes, and the sentence that says who wants it is
where they said it: that colleague is whom "it" is sent to, as the reader reads it. Only the
requester's own thing counts ("Wang wants Zhang's file" is a wish about another's thing, which
its owner decides), and only "it"/"them" handed on with no receiver of its own ("send it to
Mo" names Mo; "Rich wants it on the board" wants no thing of the requester's). "Wang's after
my stapler" is the same wish: its "'s" is "is", and "after" the requester's own thing wants
it (fix154a class 2); "after the meeting" is a time."""

from __future__ import annotations

from collections.abc import Callable, Sequence

from assistantx.core.wanted_to_have import REACH, want_of_having

# the wish or need said right after the colleague's name
_WANTS = frozenset({"wants", "needs", "want", "need", "wanted", "needed"})
# "Wang's after my stapler": "'s" (is) and "after", which wants the thing
_AFTER = "after"
# the requester's own thing, right after the wish
_OWN = frozenset({"my", "our"})
# the thing handed over, said again
_IT = frozenset({"it", "them"})
# a receiver of its own after "it": "send it to Mo", "forward it on to Mo"
_RECEIVING = frozenset({"to", "for", "with"})


def wants_own_thing(words: Sequence[str], end: int, *, folded_is: bool = False) -> bool:
    """Whether the folded ``words`` right after a name ending at ``end`` say the person
    wants or needs the requester's own thing ("wants my report"); ``folded_is``: the name
    was written with "'s", which before "after" is "is" ("Wang's after my stapler": is
    after, wants it), as the reader reads it."""
    having = 0 if folded_is else want_of_having(words[end : end + REACH])
    if having:  # "wants to borrow my report": the want of having it (``core.wanted_to_have``)
        return end + having < len(words) and words[end + having] in _OWN
    if end + 1 >= len(words) or words[end + 1] not in _OWN:
        return False
    return words[end] == _AFTER if folded_is else words[end] in _WANTS


def wishes_said(words: Sequence[str], end: int, *, folded_is: bool = False) -> bool:
    """``wishes``, and "<name>'s after ..." (``folded_is``) said as a wish too."""
    return end < len(words) and words[end] == _AFTER if folded_is else wishes(words, end)


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
