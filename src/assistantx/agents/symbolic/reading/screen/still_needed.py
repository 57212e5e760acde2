"""The speaker's own need of the thing an errand was just called off for: "don't shred my
document, I still need it for the 5:30 meeting", "please don't copy my contract yet, I still
need to edit it". After a negated errand, a need said by the speaker of what was named before
("it", "them", "this") or of their own doing ("to edit it") says why the errand is not wanted:
a reason, answered in words; nothing moves and nobody is asked who should get the thing. A
need of a thing of its own ("don't bring me coffee, I need a water instead") is a request,
read as before."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.pieces import Piece
from assistantx.core import english

_NEED = english.words("need_verbs")
# The speaker as the need's subject, and the words that only stress it ("I *still* need it")
_SPEAKER = frozenset({"i", "we", "id", "ill", "im", "ive"})
_STRESS = frozenset({"still", "really", "do", "actually", "just", "kinda", "kind", "of", "will"})
# What points back to the thing named before: "need *it*", "need *them* for ..."
_BACK = frozenset({"it", "them", "this", "that", "these", "those"})
# What may follow the thing needed in a reason: why or till when ("need it *for* the
# meeting", "*until* Friday"); anything else ("need it scanned", "need it now", "need it on
# my desk") asks for work on it or for it brought, and is read as before
_REASON_TAIL = frozenset(
    {"for", "until", "till", "til", "later", "tomorrow", "today", "tonight", "myself", "first"}
    | {"this", "anyway", "though", "tho", "still", "as", "because", "cos", "since", "while"}
)


def still_needed(piece: Piece) -> bool:
    """Whether ``piece`` is the speaker's need of the thing said before, or of their own
    doing ("I still need to edit it"), and asks nothing of the robot."""
    if piece.asks or piece.acts.imperative or piece.acts.question is not None:
        return False
    words = [w for w in piece.words if w not in ("please", "pls", "but", "because", "as", "cos")]
    if not words or words[0] not in _SPEAKER:
        return False
    k = 1
    while k < len(words) and words[k] in _STRESS:
        k += 1
    if k >= len(words) or words[k] not in _NEED:
        return False
    after = words[k + 1 :]
    if after[:1] == ["to"]:
        return True  # "need to edit it": the speaker's own doing
    # "need it (for the meeting)": the thing before, kept, and why or till when
    return after[:1] != [] and after[0] in _BACK and (len(after) == 1 or after[1] in _REASON_TAIL)
