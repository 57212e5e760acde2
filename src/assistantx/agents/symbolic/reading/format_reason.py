"""A reason that names a format, said after the request: "scan my duty return pls, customs want
a pdf", "scan my form, HR want it emailed", "print my letter as the bank needs a hard copy".

Someone outside the request (no colleague of the office, not the speaker nor the one spoken
to) wanting the result in some form ("a pdf", "an email", "a copy", "it emailed") says why the
work is asked, not a second errand: the robot cannot hand anything to the bank or to customs,
and read as a want of the speaker's it was a file passed back to its own owner (moving
nothing) or a question whom the document goes to. The clause is dropped before reading; the
request before it is read as said. A colleague's want ("scan my form, Mark wants a pdf") is a
part of the request of its own and stays, and so does the clause said alone (nothing before
it is asked). A pronoun's want after a request that names a colleague ("print my sheet and
give it to Mao? he'd like it on paper") is that colleague's, the one already served: the
reason too (read as its own want it fetched the office's paper for the speaker).
"""

from __future__ import annotations

import re
from collections.abc import Callable

from assistantx.core import english

_FORMATS = english.entries("format_nouns")
_DONE = english.entries("format_participles")
_SPEAKERS = frozenset({"i", "we", "you", "u", "ya"})


def _alternatives(phrases: tuple[str, ...]) -> str:
    ordered = sorted(phrases, key=len, reverse=True)
    return "|".join(r"\s+".join(re.escape(w) for w in p.split()) for p in ordered)


_WORD = r"[^\W\d_][\w&-]*"
_REASON = re.compile(
    # a pause or a sentence's end after the request, perhaps "as"/"because"
    r"(?P<cut>\s*(?:[,;.!?]+|\s[-–—]+)\s*(?:(?:as|because|cos|coz|since)\s+)?"
    rf"(?P<who>(?:{_WORD}\s+){{0,2}}?{_WORD})(?:\s+|(?=['’]d\s))"  # "he'd like": no space
    r"(?:want|wants|wanted|need|needs|needed|require|requires|prefer|prefers"
    r"|(?:would|\'d|’d)\s+like|(?:have\s+|has\s+)?asked\s+for|only\s+(?:take|takes|accept|accepts))\s+"
    rf"(?:(?:a|an|the|one)\s+(?:{_alternatives(_FORMATS)})"
    rf"|(?:it|them|one)\s+(?:{_alternatives(_DONE)}))"
    r")\s*(?:pls|please|thanks|thx|ta)?\s*[.!]*\s*$",
    re.IGNORECASE,
)


def without_format_reasons(text: str, is_person_word: Callable[[str], bool]) -> str:
    """``text`` without a closing clause in which someone outside the request wants the
    result in some form ("..., the bank wants a pdf")."""
    m = _REASON.search(text)
    if m is None or not text[: m.start("cut")].strip():
        return text  # nothing asked before it: said alone, it is read as before
    who = m.group("who").split()
    if who[0].lower() in _SPEAKERS:
        return text  # "..., I need a pdf": the speaker's own want, a part of the request
    if len(who) == 1 and who[0].lower() in ("they", "he", "she"):
        asked = re.findall(_WORD, text[: m.start("cut")])
        if any(is_person_word(w) for w in asked):
            # "print my sheet and give it to Mao? he wants it on paper": the one the request
            # already serves, wanting its result in that form, says why; no second errand
            return text[: m.start("cut")]
        return text  # "..., she needs a pdf": whose want is not said, a part of the request
    if any(is_person_word(w) for w in who):
        return text  # "..., Mark wants a pdf": a colleague's want, a part of its own
    return text[: m.start("cut")]
