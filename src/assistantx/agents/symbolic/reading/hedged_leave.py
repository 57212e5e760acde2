"""A request hedged as a hope about someone's leave: "i hope mark won't mind if i borrow his
ruler", "hope you don't mind if I take the last stapler". What follows "if I" is what the
speaker asks to do, said softly; the hope is politeness, no statement of fact. With "but"
("i hope mark won't mind but i need his ruler") it had been read as asked, and without it as
told ("Noted."). The clause is said as the question it means ("..., can I borrow his ruler"),
so the reader reads the ask as it reads any other: the owner is asked as always.

Only a verb in its plain form after "if I" counts: "i hope mark won't mind if i borrowed his
ruler" tells of a thing done and is left as said."""

from __future__ import annotations

import re

from assistantx.core import english, language

# the verbs of the hope, kept here: "hope" is a colleague's name in some offices
_HOPING = r"(?:hope|hoping|trust|trusting)"
_MINDING = "|".join(
    re.escape(entry).replace(r"\ ", r"\s+").replace("nt", "n['’]?t")
    for entry in sorted(english.entries("hedged_minding"), key=len, reverse=True)
)
_HEDGED = re.compile(
    rf"\b(?P<hope>{_HOPING}\s+(?:[^\W\d_]+(?:['’]s)?\s+){{1,3}}?(?:{_MINDING}))"
    rf"\s+if\s+(?P<who>i|we)\s+(?P<verb>[^\W\d_]+)\b",
    re.IGNORECASE,
)


def hedged_leaves(text: str) -> str:
    """``text`` with each "hope X won't mind if I <verb>" said as "hope X won't mind, can I
    <verb>"."""

    def asked(m: re.Match[str]) -> str:
        verb = m.group("verb")
        if verb.lower() not in language.verb_lemmas(verb.lower()):
            return m.group(0)  # "if i borrowed": a thing done, or no verb: as said
        return f"{m.group('hope')}, can {m.group('who')} {verb}"

    return _HEDGED.sub(asked, text)
