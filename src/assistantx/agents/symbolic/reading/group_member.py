"""One of a group said as the subject of a clause: "one of the juniors took a puck to the
shin", "one of the interns spilled coffee on the stapler". The subject is one person named by
what they are, as "a junior" is; read with "one of the" in front, the clause was no statement
and the things it named were fetched besides the thing asked (blind round 193: an ice pack
asked, a puck and plasters brought too). Written as that one ("a junior took ..."), the
readings of told clauses and of needs of people named by what they are take it. Only before a
verb, and only a plural noun that names no thing of the office: "bring me one of the staplers"
keeps its reading."""

from __future__ import annotations

import re
from collections.abc import Container

from assistantx.core import language

_GROUP = re.compile(
    r"\b(?P<one>one)\s+of\s+(?:the|those|these|our|my|your|his|her|their)\s+"
    r"(?P<group>[^\W\d_]+)\s+(?P<verb>[^\W\d_']+)",
    re.IGNORECASE,
)


def group_member(text: str, office_words: Container[str]) -> str:
    """``text`` with "one of the <people> <verb>" said as "a <person> <verb>"."""

    def one(m: re.Match[str]) -> str:
        group, verb = m.group("group"), m.group("verb")
        nouns = language.lemmas(group).get("NOUN", ())
        if not nouns or group.lower() in office_words or not language.is_plural_noun(group):
            return m.group(0)
        if not language.lemmas(verb).get("VERB") or "NOUN" in language.lemmas(verb):
            return m.group(0)  # "one of the interns' mugs", "one of the team leads"
        single = nouns[0]
        if single in office_words:
            return m.group(0)
        article = "an" if single[0] in "aeiou" else "a"
        if m.group("one")[0].isupper():
            article = article.capitalize()
        return f"{article} {single} {verb}"

    return _GROUP.sub(one, text)
