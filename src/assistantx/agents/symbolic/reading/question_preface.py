"""A preface that announces a question: "frank question: who's got a stapler I could use
tomorrow?", "quick q - anyone have a calculator ...", "honest question, ...". One or two
adjectives (words the dictionary knows as such: "frank", "quick", "honest", "random") and a
noun of asking (``preface_nouns``), then a colon, a dash or a comma, opening the message, a
sentence or a part after a comma: it names nobody and asks nothing, and is dropped, so what
follows is read as if said alone. Read as said, the adjective was a colleague's name when one
is called so ("Frank"), and the question a request made of them now. "Frank, who's got a
stapler?" (the comma before the noun of asking: Frank addressed) and "Wang question: ..." (no
adjective) are left as said."""

from __future__ import annotations

import re

from assistantx.core import english, language

# "frank question:", "quick q -", "honest question,": up to two words before the noun of
# asking, then its stop, at the start of the message, of a sentence or after a comma ("hey,
# random q: ...")
_PREFACE = re.compile(
    rf"(?:^|(?<=[.!?,])\s+)((?:[a-z]+\s+){{1,2}})(?:{english.alternation('preface_nouns')})"
    r"\s*(?::|,|\s[-–—]+)\s*",
    re.IGNORECASE,
)


def without_question_preface(text: str) -> str:
    """``text`` without the prefaces that announce a question (see the module)."""

    def dropped(m: re.Match[str]) -> str:
        said = m.group(1).lower().split()
        if not all("ADJ" in language.lemmas(w) for w in said):
            return m.group(0)
        return " " if m.start() else ""

    return _PREFACE.sub(dropped, text)
