"""The item a requester names when asked "Which item do you mean …?", put in the place of
the noun the request said but the office does not know.

"send my signed statement by courier to Crown Court" in an office whose paper has no name
"statement" asks "Which item do you mean for me to send by courier?"; the answer "The
document." is that statement. Read after the request as a sentence of its own, "the
document" had no owner and the reader asked "Whose document do you mean?", though the
request said "my". The answer takes the place of the unknown head noun instead ("send my
signed document by courier to Crown Court"), so everything else the request said (whose it
is, where it goes, the work) stays as said.
"""

from __future__ import annotations

import re

from assistantx.agents.symbolic.reading.frames import WHICH_ITEM
from assistantx.agents.symbolic.reading.lexicon import Lexicon
from assistantx.core.office import Office

# "my signed statement by courier": a determiner, up to two words, then the head noun before a
# preposition, a conjunction or the end of the clause
_NOUN_PHRASE = re.compile(
    r"\b(?:my|our|the|his|her|their)\s+((?:[\w'-]+\s+){0,2}?)([\w'-]+)"
    r"(?=\s+(?:by|to|for|from|with|at|and|please|via|in|on|off|over|back)\b|\s*[,.!?;:]|\s*$)",
    re.IGNORECASE,
)


def with_item_answered(
    lex: Lexicon, office: Office, text: str, question: str, answer: str
) -> str | None:
    """``text`` with its unknown head noun replaced by the one item ``answer`` names, to a
    "Which item do you mean …?" ``question``; None when the question is another, the answer
    names no item or several, or
    the request has no noun the office does not know. An answer that says whose ("Ana's
    contract", "my contract") takes the place of the whole noun phrase, its owner with it."""
    if not question.startswith(WHICH_ITEM):
        return None
    said = lex.read(answer).mentions
    items = {i for m in said if m.kind == "item" for i in m.ids}
    if len(items) != 1:
        return None
    whose = any(m.kind in ("person", "self") for m in said)  # "Ana's contract", "my one"
    phrase = _ARTICLE.sub("", answer.strip().rstrip(" .!?"))
    if whose and len(phrase.split()) > _LONGEST_ANSWER:
        return None  # a sentence, not a name of the thing: read as before
    name = office.item_type(next(iter(items))).name
    for match in _NOUN_PHRASE.finditer(text):
        head = match.group(2)
        if any(m.kind != "word" for m in lex.read(head).mentions):
            continue  # a name, a pronoun or a task word: not the noun asked about
        if whose:  # whose it is, as the answer says: "courier Ana's contract to …"
            return f"{text[: match.start()]}{phrase}{text[match.end(2) :]}"
        return f"{text[: match.start(2)]}{name}{text[match.end(2) :]}"
    return None


_ARTICLE = re.compile(r"^(?:it's\s+|it is\s+)?(?:the|a|an)\s+", re.IGNORECASE)
_LONGEST_ANSWER = 4
