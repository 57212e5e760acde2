"""A pronoun of whose for an outsider the sentence opens on: "customer at counter 1 wants a
copy of *their* contract, can you photocopy the one on my desk", "a visitor needs *his* form
stamped". The sentence's subject is a person named by what they are (``outsider_nouns``), so
"their"/"his"/"her" after it, with no colleague named between, is that person's: said as "the
customer's", which the reader already takes for an outsider's paper, in the speaker's hand
(``outsider_owner``). Before, "their" was asked about ("Who do you mean by 'their'?"), and
nobody of the office could answer.

Only the first clause's subject, a singular noun that names one person (not "someone",
"people") and no verb said first ("courier my document to her office": a command), and only
a paper the office works on after the pronoun (``papers``: "their contract"); an office thing
an outsider is said to own ("the client wants his stapler back") is still asked about, and a
colleague named before the pronoun is whom it may mean, so it is left as said."""

from __future__ import annotations

import re
from collections.abc import Callable, Collection

from assistantx.core import english

_VAGUE = frozenset({"someone", "somebody", "person", "people", "men", "women", "guys", "ladies"})
_OUTSIDERS = sorted(english.words("outsider_nouns") - _VAGUE, key=len, reverse=True)
_SUBJECT = re.compile(
    r"^\s*(?:(?:a|an|the|this|that|our|my)\s+)?(?P<noun>" + "|".join(_OUTSIDERS) + r")\b",
    re.IGNORECASE,
)
_WHOSE = re.compile(r"\b(?:their|his|her)\b(?=\s+[^\W\d_])", re.IGNORECASE)
_CLAUSE_END = re.compile(r"[.!?,;]")
# what follows a verb said first, never an outsider's noun ("courier *my* document")
_OBJECT_FIRST = frozenset({"my", "the", "a", "an", "his", "her", "their", "it", "this", "them"})
_WORD = re.compile(r"[^\W\d_]+")


def outsider_pronouns(text: str, is_person: Callable[[str], bool], papers: Collection[str]) -> str:
    """``text`` with the first clause's pronouns of whose before a paper said as its outsider
    subject's."""
    subject = _SUBJECT.match(text)
    if subject is None:
        return text
    after = _WORD.match(text, len(text) - len(text[subject.end() :].lstrip()))
    if subject.start("noun") == len(text) - len(text.lstrip()) and (
        after is not None and after.group(0).lower() in _OBJECT_FIRST
    ):
        return text  # "courier my document to her office": the verb, said first
    end = _CLAUSE_END.search(text, subject.end())
    stop = end.start() if end else len(text)
    noun = subject.group("noun").lower()
    out: list[str] = []
    last = subject.end()
    for whose in _WHOSE.finditer(text, subject.end(), stop):
        between = text[subject.end() : whose.start()]
        if any(is_person(w) for w in _WORD.findall(between)):
            break  # "the customer gave Wang their form": Wang's, maybe
        thing = _WORD.match(text, whose.end() + 1)
        if thing is None or thing.group(0).lower() not in papers:
            continue  # "his stapler": an office thing an outsider has, asked about
        out.append(text[last : whose.start()])
        out.append(f"the {noun}'s")
        last = whose.end()
    if not out:
        return text
    return text[: subject.end()] + "".join(out) + text[last:]
