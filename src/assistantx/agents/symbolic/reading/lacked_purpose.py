"""Someone's lack of a thing for a purpose, said as what they have not: "Hal has nothing to
write with", "I'm pinning up a hem and have nothing to measure it with", "got nothing to cut
with", "nothing to measure it with", "no way to measure it".

Having nothing to do a thing *with* is needing something to do it with: the lack names the
thing by its use, as "something to write with" does, and the office's item declared for that
use (its ``purposes``) is the one wanted, brought to whoever lacks it. The rewrite says the
need ("Hal needs something to write with", "I need something to measure it with") and the
reader's purpose rule picks the item; the object the purpose works on ("it", "the hem")
stays with the purpose, never brought.

English leaves the lacking subject out in chat ("got nothing to cut with", "nothing to
measure it with"): at a clause's start the lack is the speaker's. Those clipped forms, and
the lack with an object or with "no way to" and no "with" ("no way to measure it"), are read
only where the verb is one an item of the office is declared for: "I have nothing to do" and
"nothing to report" name no use of any thing, and stay what they are.
"""

from __future__ import annotations

import re
from collections.abc import Collection

from assistantx.core import language

_HAVE = r"(?P<have>has|have|['’]s|['’]ve|s|ve)\s+(?:got\s+)?"
# a clause's start: the message's, after a stop or a comma, or after a joining word
_CLAUSE_START = r"(?P<start>^\s*|(?<=[,.;:!?])\s*|\b(?:and|but|so)\s+)"
# what the purpose works on: a determiner and its noun ("the hem", "this ribbon") before a
# pronoun ("this"), and never the "with" itself
_OBJECT = (
    r"(?P<object>\s+(?:(?:the|my|our|his|her|their|your|this|that|these|those|a|an|some)"
    r"(?:\s+(?!with\b|on\b)[a-z]+){1,2}?|it|them|this|that|these|those|one))?"
)
# subjects of a lack that is no one's ("there's no way to ...", "it has nothing to ...")
_NO_ONE = frozenset({"there", "it", "that", "this", "which"})
# subjects that take "need", said before a clipped "got nothing"
_PLAIN_SUBJECTS = frozenset({"i", "we", "you", "they"})
_LACKED = re.compile(
    rf"(?:\b{_HAVE}|\b(?P<got>got)\s+|{_CLAUSE_START})"
    r"(?P<none>nothing|no\s+way)\s+to\s+(?P<verb>[a-z]+)"
    rf"{_OBJECT}(?P<with>\s+(?:with|on)\b)?",
    re.IGNORECASE,
)


def lacked_purposes(text: str, declared: Collection[str]) -> str:
    """``text`` with each lack of a thing for a purpose said as the need of something for it
    ("Hal has nothing to write with" -> "Hal needs something to write with"). ``declared``:
    what the office's items are declared for, in lower case ("measure", "write on"), built
    once per office by the caller (this runs on every message)."""

    def need(match: re.Match[str]) -> str:
        verb, said_with = match.group("verb"), (match.group("with") or "").strip().lower()
        if not said_with and match.group("none").lower() == "nothing":
            return match.group(0)  # "nothing to report": no thing to do it with is said
        plain = match.group("have") is not None and said_with and not match.group("object")
        if not plain and not _declared(verb, said_with, declared):
            return match.group(0)  # "no way to fix it": no use of a thing of the office
        before = text[: match.start()].split()
        if not plain and before and before[-1].lower() in _NO_ONE:
            return match.group(0)  # "there's no way to charge it here": nobody's lack
        purpose = f"something to {verb}{match.group('object') or ''}{match.group('with') or ''}"
        said_have = match.group("have") or ""
        if said_have:
            have = said_have.lower().lstrip("'’")
            # "I've nothing" -> "I need": the contraction's apostrophe went with "have"
            space = " " if said_have[0] in "'’" else ""
            return f"{space}{'needs' if have in ('has', 's') else 'need'} {purpose}"
        if match.group("got") is not None:
            # "we got nothing to cut with", "Min got ...": the subject said; "(I) got ..."
            if before and before[-1].lower() in _PLAIN_SUBJECTS:
                return f"need {purpose}"
            if before and before[-1][:1].isupper() and before[-1].isalpha():
                return f"needs {purpose}"
            return f"I need {purpose}"
        # the speaker's lack at a clause's start: "nothing to measure it with", "and ..."
        start = match.group("start") or ""
        joining = f"{start.strip()} " if start.strip() else ""
        return f"{' ' if start[:1].isspace() else ''}{joining}I need {purpose}"

    return _LACKED.sub(need, text)


def _declared(verb: str, said_with: str, declared: Collection[str]) -> bool:
    """Whether an item of the office is for ``verb`` (its lemma): "measure", or "write on"
    where "on" is said (paper is to write on, never to write "with")."""
    lemmas = language.verb_lemmas(verb.lower()) | {verb.lower()}
    if said_with == "on":
        return any(f"{lemma} on" in declared for lemma in lemmas)
    return any(lemma in declared for lemma in lemmas)
