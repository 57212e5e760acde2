"""A small newsroom for the tests of blind round 16's classes (the round's own office and
sentences were never read). People named with diacritics (Åsa, Ramón, Łukasz, Zoë) who each
own a long lens and a camera; people whose first names are ordinary English words (Mark,
Will, Sunny, Frank); an editor with a role alias ("the Publisher"); a standards desk named by an
adjective ("standards", "compliance") that reads page proofs and gives them back; a courier
whose verbs include "run"; a printer whose input is the running sheet; a trimmer whose verbs
include "cut" beside a cutting mat; a light meter and a magnifying glass to borrow; negative
strips (synonym "negatives") that people hold."""

from __future__ import annotations

import functools
from typing import Any

from assistantx.core.office import Office, parse_office

_PEOPLE: tuple[tuple[str, str, list[str], list[dict[str, Any]]], ...] = (
    (
        "ines",
        "Ines Duarte",
        [],
        [{"type": "page_proof"}, {"type": "running_sheet"}, {"type": "file"}],
    ),
    (
        "asa",
        "Åsa Lindgren",
        [],
        [{"type": "long_lens"}, {"type": "camera"}, {"type": "negative_strip"}],
    ),
    ("ramon", "Ramón Ibáñez", [], [{"type": "long_lens"}, {"type": "camera"}]),
    ("lukasz", "Łukasz Nowak", [], [{"type": "long_lens"}, {"type": "light_meter"}]),
    ("zoe", "Zoë Marchetti", [], [{"type": "camera"}, {"type": "page_proof"}]),
    ("mark", "Mark Ellison", [], [{"type": "cutting_mat"}, {"type": "magnifying_glass"}]),
    ("will", "Will Tanner", [], [{"type": "light_meter"}, {"type": "page_proof"}]),
    ("sunny", "Sunny Rao", [], [{"type": "magnifying_glass"}]),
    ("bjorn", "Bjørn Haugen", [], [{"type": "long_lens"}, {"type": "camera"}]),
    ("frank", "Frank Osei", [], [{"type": "cutting_mat"}]),
    ("bea", "Beatrix Holm", ["Bea", "the Publisher"], [{"type": "running_sheet"}]),
)


def raw_newsroom() -> dict[str, Any]:
    return {
        "name": "newsroom",
        "locations": [
            *(
                {"id": f"desk_{n}", "kind": "workstation", "name": f"Desk {n}", "x": x, "y": 6.0}
                for n, x in enumerate(
                    (5.0, 9.0, 13.0, 17.0, 21.0, 25.0, 29.0, 33.0, 37.0, 41.0, 45.0), 1
                )
            ),
            {"id": "print_room", "kind": "facility", "name": "Print room", "x": 4.0, "y": 20.5},
            {"id": "back_office", "kind": "facility", "name": "Back office", "x": 20.0, "y": 20.5},
            {"id": "post_room", "kind": "facility", "name": "Post room", "x": 30.0, "y": 20.5},
        ],
        "item_types": [
            {"id": "long_lens", "name": "long lens", "synonyms": ["telephoto"]},
            {"id": "camera", "name": "camera"},
            {"id": "light_meter", "name": "light meter", "synonyms": ["exposure meter"]},
            {"id": "magnifying_glass", "name": "magnifying glass", "synonyms": ["eyeglass"]},
            {"id": "cutting_mat", "name": "cutting mat"},
            {
                "id": "negative_strip",
                "name": "negative strip",
                "kind": "personal",
                "synonyms": ["negatives"],
            },
            {
                "id": "page_proof",
                "name": "page proof",
                "kind": "personal",
                "synonyms": ["proof"],
            },
            {
                "id": "running_sheet",
                "name": "running sheet",
                "kind": "personal",
                "synonyms": ["rundown"],
            },
            {
                "id": "file",
                "name": "electronic file",
                "kind": "electronic",
                "synonyms": ["file", "draft"],
            },
            {"id": "printout", "name": "printout", "kind": "product", "synonyms": ["hard copy"]},
        ],
        "operations": [
            {"id": "vet", "name": "standards read", "verbs": ["vet"], "input": "page_proof"},
            {
                "id": "courier",
                "name": "courier",
                "verbs": ["courier", "run", "dispatch"],
                "input": "page_proof",
                "sends_out": True,
                "destination_asked": "the name and address of the place",
            },
            {
                "id": "print",
                "name": "print",
                "verbs": ["print"],
                "input": "file",
                "product": "printout",
            },
            {
                "id": "shred",
                "name": "shred",
                "verbs": ["shred"],
                "input": "page_proof",
                "consumes": True,
            },
            {"id": "trim", "name": "trim", "verbs": ["trim", "cut"], "input": "printout"},
        ],
        "people": [
            {
                "id": pid,
                "name": name,
                "aliases": aliases,
                "location": f"desk_{n}",
                "handle": f"@{pid}",
                "owns": owns,
            }
            for n, (pid, name, aliases, owns) in enumerate(_PEOPLE, 1)
        ],
        "facilities": [
            {
                "id": "standards_desk",
                "name": "standards desk",
                "synonyms": ["standards", "the standards team", "compliance", "editorial"],
                "location": "back_office",
                "operations": ["vet"],
                "guards": ["mark"],
            },
            {
                "id": "courier_desk",
                "name": "courier desk",
                "location": "post_room",
                "operations": ["courier", "shred"],
                "guards": ["sunny"],
            },
            {
                "id": "printer",
                "name": "printer",
                "location": "print_room",
                "operations": ["print"],
                "guards": ["will"],
                "products": ["printout"],
            },
            {
                "id": "trimmer",
                "name": "trimmer",
                "location": "print_room",
                "operations": ["trim"],
                "guards": ["will"],
            },
        ],
        "groups": [{"id": "all", "name": "Everyone", "members": [p[0] for p in _PEOPLE]}],
        "robot": {"home": "print_room"},
    }


@functools.cache
def newsroom() -> Office:
    return parse_office(raw_newsroom(), "newsroom")
