"""Whom "his"/"her"/"him" means when the request's own words name nobody: the one colleague
the whole message names, also in a piece the screen set aside ("Is Otto in? I need his
ruler, could you fetch it for me": the question about Otto is context, and "his" is Otto's).
Only when the message names exactly one colleague besides the requester, each name meaning
one person; with none or several, whom is still asked.
"""

from __future__ import annotations

from assistantx.agents.symbolic.reading.lexicon import Lexed


def the_one_named(whole: Lexed, requester: str) -> str | None:
    """The one colleague (not the requester) the message names, or None."""
    people: set[str] = set()
    for m in whole.mentions:
        if m.kind != "person":
            continue
        if len(set(m.ids)) != 1:
            return None  # a name two people share: whom is asked
        people.add(m.ids[0])
    people.discard(requester)
    return next(iter(people)) if len(people) == 1 else None


def the_ones_named(whole: Lexed, requester: str) -> tuple[str, ...]:
    """The colleagues (not the requester) the message names, in order, each once; a name two
    people share names nobody here ("them both" of it is asked)."""
    people = [m.ids[0] for m in whole.mentions if m.kind == "person" and len(set(m.ids)) == 1]
    return tuple(p for p in dict.fromkeys(people) if p != requester)
