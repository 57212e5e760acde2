"""Whose the tool is where it is said by its work's word: where the seal's only names are
"clerk's stamp" or "notary stamp", a bare "stamp" is read as the work's verb, and "bring me
Siobhan's stamp" then asks for the tool itself; the possessive right before that word says
whose (Siobhan's, never any seal of the office). "my stamp" is the speaker's."""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Mention


def cued_tool_owner(mentions: Sequence[Mention], cue: Mention, requester: str) -> str | None:
    """The owner said by the possessive right before ``cue`` in ``mentions``; None if none."""
    n = next((k for k, m in enumerate(mentions) if m is cue), 0)
    before = mentions[n - 1] if n > 0 else None
    if before is None or not before.possessive:
        return None
    if before.kind == "person" and len(before.ids) == 1:
        return before.ids[0]
    return requester if before.kind == "self" else None
