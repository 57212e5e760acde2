"""The person names a command line takes (``--as``, ``--unavailable``), matched like any name a
person types: by the office's tolerant grounding (case, titles, small typos), never by raw id."""

from __future__ import annotations

from assistantx.core.office import Office, PersonId
from assistantx.memory.resolve import Resolver


def resolve_people(
    office: Office, requester: str, unavailable: str
) -> tuple[PersonId, tuple[PersonId, ...]]:
    """The requester's id and the absent people's ids; raises GroundingError on a bad name."""
    resolver = Resolver(office)
    return resolver.person(requester), resolver.people_list(unavailable)
