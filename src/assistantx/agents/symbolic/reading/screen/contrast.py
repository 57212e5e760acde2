"""Contrast: "the file not a printout", "as a PDF, not a hard copy", "not a printout": a
fragment beside a request that says which kind of thing is meant by contrast with another
kind of the office. It asks for nothing of its own (never a print of the thing rejected), so
it is set aside as context; the kind it chooses ("the file") names the request's own object
when the office has no word for it ("send me his yr9 scheme of work, the file not a
printout": his file), by the rewrites (``rewrites.chosen_kind``)."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.screen.english import DETERMINERS
from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms

# Words a contrast may open with or be padded by ("*just as* the file, not a printout").
_OPENERS = frozenset({"as", "in", "just", "only", "but", "please", "thanks", "though", "ta"})
CHOSEN = "kind:"  # the context entry of the chosen kind ("kind:file")


def contrast(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    if piece.acts.request or len(msg.pieces) < 2:
        return None  # a contrast stands beside what it qualifies
    tokens, mentions = piece.lexed.tokens, list(piece.lexed.mentions)
    words = [t.word for t in tokens]
    if "not" not in words:
        return None
    cut = words.index("not")
    rejected = _only_thing(terms, mentions, words, cut + 1, len(words))
    if rejected is None:
        return None
    chosen = _only_thing(terms, mentions, words, 0, cut) if cut else None
    if cut and chosen is None:
        return None  # "send it today not tomorrow": no contrast of kinds
    context = (f"{CHOSEN}{chosen}",) if chosen is not None and chosen != rejected else ()
    meaning = f"not {terms.office.item_type(rejected).name}"
    return Finding("statement", piece, meaning, context=context)


def _only_thing(
    terms: Terms, mentions: list[Mention], words: list[str], start: int, end: int
) -> str | None:
    """The one item kind words [start, end) name, with nothing else among them but
    determiners and padding ("the file", "a hard copy"); None otherwise."""
    inside = [m for m in mentions if start <= m.start and m.end <= end]
    things = [(m, item) for m in inside if (item := _item_of(terms, m)) is not None]
    if len(things) != 1:
        return None
    m, item = things[0]
    rest = [w for k, w in enumerate(words[start:end], start) if not m.start <= k < m.end]
    if any(w not in DETERMINERS and w not in _OPENERS for w in rest):
        return None
    return item


def _item_of(terms: Terms, m: Mention) -> str | None:
    """The item kind a mention names: an item, or a word of a service that is also an item's
    name ("a copy")."""
    if m.kind == "item" and len(m.ids) == 1:
        return m.ids[0]
    return terms.lex.items.get(m.text.lower()) if m.kind == "cue" else None
