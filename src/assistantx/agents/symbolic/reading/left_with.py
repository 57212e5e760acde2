"""A thing left with a person is handed to them: "drop it with her", "leave the printout with
him", "drop it off with her". English says the same of a name ("leave it with Zhang", read as
the recipient by the person rules); a "him"/"her" after such a "with" is that recipient too,
the one colleague the message named before it, never the speaker (fix154a class 4: "Eilidh
needs the stats ..., print my spreadsheet and drop it with her" handed the printout to the
speaker). Only a verb of putting down or handing makes the "with" a hand-over: "go through it
with her", "check it with him" name no recipient."""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.core import english, language

# "leave", "drop", "pop", "pass", "hand": what puts a thing down or hands it over; not the
# putting verbs whose "with" says together or how ("set it up with her", "stick it with
# tape", "show it with him")
_LEAVING = (english.words("putting_verbs") | english.words("handing_verbs") | {"hand"}) & {
    "leave",
    "drop",
    "pop",
    "put",
    "place",
    "hand",
    "pass",
    "deliver",
    "forward",
    "send",
}
# what may stand between the verb and its "with": the thing and a particle ("drop *it off*
# with her", "leave *the printout* with him"), never another clause
_CLAUSE_ENDS = frozenset({"and", "then", "but", "or", "so", "because", "while"})
_REACH = 6


def left_with(words: Sequence[str], at: int) -> bool:
    """Whether the word at ``at`` follows a "with" whose clause's verb puts the thing down or
    hands it over, within a few words before it."""
    if at < 2 or words[at - 1] != "with":
        return False
    for k in range(at - 2, max(-1, at - 2 - _REACH), -1):
        if words[k] in _CLAUSE_ENDS:
            return False
        if language.verb_lemmas(words[k]) & _LEAVING:
            return True
    return False
