"""Each thing's own "for X" in a list of two: "a latte for me and a copy of my contract for
Fang". When a clause is read as two parts, each with its own things (a product named with
what it is made of, beside another thing: ``TaskReader._made_of_apart``), and each part names
someone right after its own things ("for me", "to Wang"), that person receives that part's
things: X receives A and Y receives B. Reading both parts with the clause's last recipient
gave the latte to Fang, a wrong physical action.

Where only one part names whom it is for ("a coffee and a copy of my contract for Fang"), the
clause's roles stand as before, read whole."""

from __future__ import annotations

import dataclasses
from collections.abc import Sequence

from assistantx.agents.symbolic.reading._parties import Clause, Roles


def roles_of_parts(roles: Roles, parts: Sequence[Clause]) -> list[Roles]:
    """The roles each part (in the order said) is read with: its own recipients, said after
    its first thing and before the next part's first thing, where every part has some; else
    the clause's roles for each, as before."""
    starts = [min((m.start for m in p.objects()), default=-1) for p in parts]
    if any(s < 0 for s in starts) or starts != sorted(starts):
        return [roles for _ in parts]
    bounds = [*starts[1:], 1 << 30]
    own = [
        [(w, at) for w, at in zip(roles.recipient, roles.recipient_at, strict=True) if s <= at < e]
        for s, e in zip(starts, bounds, strict=True)
    ]
    if not all(own):
        return [roles for _ in parts]
    return [
        dataclasses.replace(
            roles, recipient=[w for w, _ in mine], recipient_at=[at for _, at in mine]
        )
        for mine in own
    ]
