"""What the office keeps at a facility or a place: the one lookup behind "the kettle in the
kitchen" (``kept_at``: whose item of a type is there) and "Jürgen's curry from the staff
fridge" (``screen.kept``: which of a person's items are there). It reads the office only, so
any stage of the reader may import it."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

from assistantx.core.office import Office

PlaceKind = Literal["facility", "place"]


@dataclass(frozen=True)
class KeptItem:
    type_id: str
    owner: str  # a person's id; for a facility's supply, the facility's id
    how: Literal["supply", "keeper", "desk"]  # a supply, kept by a facility, on a desk there


def items_kept_at(office: Office, kind: PlaceKind, where: str) -> list[KeptItem]:
    """The items at the facility ``where`` (``kind`` "facility") or at the location ``where``
    ("place"): the supplies still in stock of each facility there, in the office's order;
    then each person's belongings kept by a facility there, in the order of the people and of
    what they own; at a location, also what lies on the desk of whoever sits there (a
    belonging no facility keeps)."""
    facilities = [
        f for f in office.facilities if (f.id if kind == "facility" else f.location) == where
    ]
    ids = {f.id for f in facilities}
    found = [
        KeptItem(s.type, f.id, "supply") for f in facilities for s in f.supplies if s.count != 0
    ]
    for p in office.people:
        on_desk = kind == "place" and p.location == where
        for own in p.owns:
            keeper = office.keeper(p.id, own.type)
            if keeper is not None and keeper.id in ids:
                found.append(KeptItem(own.type, p.id, "keeper"))
            elif keeper is None and on_desk:
                found.append(KeptItem(own.type, p.id, "desk"))
    return found
