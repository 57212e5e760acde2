"""A colleague's electronic file "of", "about" or "on" one of the office's things: "Dimitris's
pdf *of the manifest*", "Ray's slides *about the contract*". An electronic file (an item
of kind "electronic" in the office file) holds words and pictures, so what follows it after
"of"/"about"/"on" is what it is about, never a second thing asked for: the phrase is left
out and the colleague's file stays ("Dimitris's pdf"), so no "whose document?" is asked
for a thing nobody wants moved.
"""

from __future__ import annotations

from assistantx.agents.symbolic.reading.aligned import aligned_reading
from assistantx.agents.symbolic.reading.lexicon import Lexicon
from assistantx.core import english
from assistantx.core.office import Office

# The prepositions that say what a file is about ("a pdf of the plan", "slides on the bid").
_ABOUT = frozenset({"of", "about", "on"})
_DETERMINERS = english.words("determiners")


def without_file_subject(lex: Lexicon, office: Office, text: str) -> str:
    """``text`` without the "of the <thing>" after a colleague's electronic file ("Wang's
    pdf of the manifest" → "Wang's pdf"); unchanged where there is none."""
    spans, tokens, mentions = aligned_reading(lex, text)
    if spans is None:
        return text
    at = {m.start: m for m in mentions}
    cuts: list[tuple[int, int]] = []
    for owner in mentions:
        if owner.kind != "person" or not owner.possessive or len(owner.ids) != 1:
            continue
        file = at.get(owner.end)
        if (
            file is None
            or file.kind != "item"
            or file.possessive
            or not _electronic(office, file.ids)
        ):
            continue
        k = file.end
        if k >= len(tokens) or tokens[k].word not in _ABOUT:
            continue
        j = k + 1
        while j < len(tokens) and tokens[j].word in _DETERMINERS:
            j += 1
        subject = at.get(j)
        if subject is None or subject.kind != "item" or _electronic(office, subject.ids):
            continue
        cuts.append((spans[k - 1][1], spans[subject.end - 1][1]))
    for start, stop in reversed(cuts):
        text = text[:start] + text[stop:]
    return text


def _electronic(office: Office, ids: tuple[str, ...]) -> bool:
    return len(ids) == 1 and office.item_type(ids[0]).kind == "electronic"
