"""A file named by who sent it: "print the invoice spreadsheet I sent", "print the slides I
emailed you", "artwork is the file i sent", "print the file Wang sent".

A relative clause "<subject> sent / emailed / shared / forwarded (you)" after a noun of the
office's electronic files says whose file it is, as a possessive would: "the spreadsheet I
sent" is the requester's own file ("my spreadsheet"), "the file Wang sent" is Wang's ("Wang's
file", asked of Wang as any colleague's file is). Read as it stood, the past "sent" was taken
for the office's own send service where one is called so ("Sorry, I'm not sure what you want
me to do with the electronic file"), and the file had no owner said. The clause is no request:
its verb is past, its subject the speaker or a colleague, and nothing comes after it but the
clause's end, whom it was sent to ("you", "to you", "over") or when ("earlier").

A noun the office names as an electronic file ("spreadsheet", "file", "deck") is read so, and
so is one it does not know at all ("the invoice workbook I sent": a thing sent to the robot
that is no item of the office is a file); one of its other items ("the document I sent":
paper the requester sent off) and "the form Wang signed" are left."""

from __future__ import annotations

import re
from collections.abc import Callable

_WORD = r"[^\W\d_][\w-]*"
_DETERMINERS = r"the|this|that|those|these"
# the verbs of sending a file, in the past: the clause tells what was done, asks for nothing
_SENT = r"sent|emailed|e-mailed|mailed|shared|forwarded|fwd|fwded|uploaded|attached|dropped"
# what may follow the verb in the clause: to whom, how, when
_TAIL = (
    r"(?:\s+(?:to\s+you|with\s+you|you|u|ya|over|across|through|round|earlier|before"
    r"|yesterday|today|just\s+now|this\s+morning|last\s+night|on\s+slack|by\s+email))*"
)
# the clause ends: its end, a stop, or a word that opens a phrase of its own
_AFTER = (
    r"(?=\s*(?:$|[,.;:!?)]|(?:and|so|then|now|please|pls|to|for|on|at|in|into|with|can"
    r"|could|would|asap)\b))"
)
_WHO = rf"{_WORD}(?:\s+(?!(?:just|has|had)\b){_WORD})?"


def relative_clauses(verb: str) -> tuple[re.Pattern[str], ...]:
    """The patterns of "<determiner> <thing> (that) <who> <verb> ..." ending its clause, for a
    ``verb`` pattern (with what may follow it): the thing's words the longest first ("the
    invoice spreadsheet I sent": not "invoice" with "spreadsheet I" taken for who sent it)."""
    return tuple(
        re.compile(
            rf"\b(?:{_DETERMINERS})\s+(?P<thing>{_WORD}(?:\s+{_WORD}){{{n - 1}}})\s+"
            rf"(?:(?:that|which)\s+)?(?P<who>{_WHO})\s+(?:just\s+|already\s+)?{verb}{_AFTER}",
            re.IGNORECASE,
        )
        for n in (3, 2, 1)
    )


_CLAUSES = relative_clauses(rf"(?:{_SENT}){_TAIL}")
_SPEAKER = "i"


def sent_files(
    text: str, is_person_word: Callable[[str], bool], as_file: Callable[[str], str | None]
) -> str:
    """``text`` with each electronic file named by who sent it said as that one's file ("the
    spreadsheet I sent" → "my spreadsheet", "the file Wang sent" → "Wang's file").
    ``as_file``: the thing's words said as a file of the office, None where they name no
    file (another item, a person)."""

    def owned(m: re.Match[str]) -> str:
        who, thing = m.group("who"), m.group("thing")
        if any(is_person_word(w) for w in thing.split()):
            return m.group(0)
        said = as_file(thing)
        if said is None:
            return m.group(0)
        if who.lower() == _SPEAKER:
            whose = "my"
        elif all(is_person_word(w) for w in who.split()):
            whose = f"{who}'s"
        else:
            return m.group(0)  # "the file the client sent": no colleague
        # nothing of the clause is kept: whom and when it was sent say no more of the file
        return f"{whose} {said}"

    for clause in _CLAUSES:
        text = clause.sub(owned, text)
    return text
