"""The default office as a library branch for the reader's tests of named places outside
(fix115d): its print room also keeps a courier desk with a send-out service that takes a
book ("send by interlibrary courier", verb "courier"), asking where to when none is said."""

from __future__ import annotations

import functools
from typing import TYPE_CHECKING, Any

from helpers.dataset_offices import DEFAULT_FILE
from helpers.yaml_files import raw_yaml

if TYPE_CHECKING:
    from assistantx.core.office import Office


@functools.cache
def library_courier() -> Office:
    raw: dict[str, Any] = raw_yaml(DEFAULT_FILE)
    raw["operations"].append(
        {
            "id": "courier",
            "name": "send by interlibrary courier",
            "verbs": ["courier"],
            "input": "book",
            "sends_out": True,
            "destination_asked": "the branch",
        }
    )
    raw["facilities"].append(
        {
            "id": "courier_desk",
            "name": "courier desk",
            "location": "print_room",
            "operations": ["courier"],
            "guards": ["xu"],
            "products": [],
        }
    )
    from assistantx.core.office import parse_office

    return parse_office(raw)
