"""A file's paper made, then the file "also" sent on: "print my report and also send it to
Wang", "print my slides and send them to Zhang as well".

After work that makes a paper from an electronic file (printing: the office's operations whose
input is electronic and whose product is not), "send it to X" may be either: the printout sent
over (the one errand, "print my report and send it to Wang"), or the file passed on. A word of
addition on that clause ("also", "too", "as well", ``in_addition``) says it is a second errand
beside the first, so the printout stays the speaker's and "it" is the file: the clause's
"send" is read as "forward", the office's word for passing a file on. Without such a word, or
with a verb of carrying ("take it to Wang"), the clause is read as before.
"""

from __future__ import annotations

import re

from assistantx.core import english
from assistantx.core.office import Office


def _phrases(key: str) -> str:
    ordered = sorted(english.entries(key), key=len, reverse=True)
    return "|".join(r"\s+".join(re.escape(w) for w in p.split()) for p in ordered)


_ADDED = _phrases("in_addition")
# "..., and also send it to Wang", "... and send them to Zhang as well": the join, a word of
# addition before or after, the verb "send" and a pronoun pointing back, then whom it goes to
_SENT_ON = re.compile(
    rf"(?P<join>(?:,\s*|\s+)(?:and\s+)?(?:then\s+)?)(?P<before>(?:{_ADDED})\s+)?"
    r"(?:(?:please|pls|can\s+you|could\s+you)\s+)?"
    r"(?P<verb>send)\s+(?:it|them|that|those|this|these)\s+"
    r"(?P<rest>(?:(?:over|on|across)\s+)?to\s+[^,.;!?]*?)"
    rf"(?P<after>\s+(?:{_ADDED}))?(?=\s*(?:[,.;!?]|$))",
    re.IGNORECASE,
)
_WORD = re.compile(r"[^\W\d_]+")


def paper_makers(office: Office) -> frozenset[str]:
    """The verbs of the office's work that makes a paper (or any thing in hand) from a file."""
    out: set[str] = set()
    for op in office.operations:
        if op.input is None or op.product is None:
            continue
        if office.item_type(op.input).kind != "electronic":
            continue
        if office.item_type(op.product).kind == "electronic":
            continue  # the file made is sent as a file whatever is said
        out.update(w.lower() for w in (*op.verbs, *op.name.split()[:1]))
    return frozenset(out)


def also_sent(text: str, makers: frozenset[str]) -> str:
    """``text`` with "send it" read as "forward it" where a word of addition makes it a
    second errand after a paper made from a file (``makers``: ``paper_makers``)."""
    if not makers:
        return text
    for m in _SENT_ON.finditer(text):
        if m.group("before") is None and m.group("after") is None:
            continue  # "print my report and send it to Wang": the printout, as before
        sentence = re.split(r"[.!?;]", text[: m.start()])[-1]
        if not any(w.lower() in makers for w in _WORD.findall(sentence)):
            continue  # nothing made from a file before it: "send" keeps its reading
        verb = m.group("verb")
        said = "Forward" if verb[:1].isupper() else "forward"
        return text[: m.start("verb")] + said + text[m.end("verb") :]
    return text
