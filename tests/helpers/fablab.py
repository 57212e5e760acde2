"""Two small workshops for the reader's tests of an office's own operations named by
several words (no blind round's office or sentences were read).

``fablab``: a plotter plots a file (its verbs "plot" and "print"); a 3D printer runs "3D
print" (verbs "3d print", "3d-print"); a laser cutter runs "laser cut" (verbs "laser",
"lasercut", "laser-cut"); people own a laser measure, a tape measure and a first aid kit
(a "kit"); a stores cupboard kept by one person "makes up a kit bag" (operation id
``bundle``, an ordinary verb that does not describe it; a product from nothing). There is no
scanner.

``costume_works``: a theatre workshop whose declared phrases overlap the same way: a vinyl
cutter ("vinyl cut", verbs "vinyl cut", "vinyl-cut"), a laser engraver ("laser engrave",
verbs "engrave", "laser engrave"), a CNC router ("rout", verbs "rout", "mill", "cnc"), a
heat press ("heat press", verbs "heat press", "heat-press") beside a wardrobe that presses
costumes (verbs "press", "steam"), and a scanner (verbs "scan")."""

from __future__ import annotations

import functools
from typing import Any

from assistantx.core.office import Office, parse_office

_DESKS = ((5.0, 6.0), (9.0, 6.0), (13.0, 6.0), (17.0, 6.0), (21.0, 6.0), (25.0, 6.0))

_FAB_PEOPLE = (
    ("ines", "Ines Varga", [{"type": "laser_measure"}, {"type": "tape"}]),
    ("tomas", "Tomas Reyes", [{"type": "laser_measure"}, {"type": "drawing"}]),
    ("hana", "Hana Ilves", [{"type": "tape"}, {"type": "drawing"}]),
    ("priit", "Priit Kask", [{"type": "drawing"}]),
    ("wanda", "Wanda Obi", [{"type": "tape"}, {"type": "first_aid_kit"}]),
    ("gus", "Gus Moreau", [{"type": "drawing"}]),
)


def _places(extra: list[dict[str, Any]]) -> list[dict[str, Any]]:
    return [
        *(
            {"id": f"desk_{n}", "kind": "workstation", "name": f"Desk {n}", "x": x, "y": y}
            for n, (x, y) in enumerate(_DESKS, 1)
        ),
        *extra,
    ]


def _people(
    people: tuple[tuple[str, str, list[dict[str, str]]], ...], file_type: str
) -> list[dict[str, Any]]:
    return [
        {
            "id": pid,
            "name": name,
            "location": f"desk_{n}",
            "handle": f"@{pid}",
            "owns": [*owns, {"type": file_type}],
        }
        for n, (pid, name, owns) in enumerate(people, 1)
    ]


def raw_fablab() -> dict[str, Any]:
    return {
        "name": "fablab",
        "locations": _places(
            [
                {"id": "workshop", "kind": "facility", "name": "Workshop", "x": 4.0, "y": 20.5},
                {
                    "id": "store_room",
                    "kind": "facility",
                    "name": "Store room",
                    "x": 14.0,
                    "y": 20.5,
                },
            ]
        ),
        "item_types": [
            {"id": "laser_measure", "name": "laser measure", "synonyms": ["laser meter"]},
            {"id": "tape", "name": "tape measure"},
            {"id": "drawing", "name": "drawing", "kind": "personal", "synonyms": ["drawings"]},
            {
                "id": "design_file",
                "name": "design file",
                "kind": "electronic",
                "synonyms": ["stl", "file"],
            },
            {"id": "plot", "name": "plot", "kind": "product", "synonyms": ["plotted sheet"]},
            {
                "id": "model_part",
                "name": "printed part",
                "kind": "product",
                "synonyms": ["3d print"],
            },
            {"id": "cut_parts", "name": "cut parts", "kind": "product", "synonyms": ["bits"]},
            {"id": "kit_bag", "name": "kit bag", "kind": "product"},
            {"id": "first_aid_kit", "name": "first aid kit", "synonyms": ["kit"]},
        ],
        "operations": [
            {
                "id": "plot",
                "name": "plot",
                "verbs": ["plot", "print"],
                "input": "design_file",
                "product": "plot",
            },
            {
                "id": "print3d",
                "name": "3D print",
                "verbs": ["3d print", "3d-print"],
                "input": "design_file",
                "product": "model_part",
            },
            {
                "id": "cut",
                "name": "laser cut",
                "verbs": ["laser", "lasercut", "laser-cut"],
                "input": "design_file",
                "product": "cut_parts",
            },
            {"id": "bundle", "name": "make up a kit bag", "product": "kit_bag"},
        ],
        "people": _people(_FAB_PEOPLE, "design_file"),
        "facilities": [
            {
                "id": "plotter",
                "name": "plotter",
                "location": "workshop",
                "operations": ["plot"],
                "guards": ["hana"],
                "products": ["plot"],
            },
            {
                "id": "printer3d",
                "name": "3D printer",
                "location": "workshop",
                "operations": ["print3d"],
                "guards": ["priit"],
                "products": ["model_part"],
            },
            {
                "id": "laser_cutter",
                "name": "laser cutter",
                "location": "workshop",
                "operations": ["cut"],
                "guards": ["priit"],
                "products": ["cut_parts"],
            },
            {
                "id": "stores",
                "name": "stores cupboard",
                "location": "store_room",
                "operations": ["bundle"],
                "guards": ["wanda"],
                "products": ["kit_bag"],
            },
        ],
        "groups": [{"id": "all", "name": "Everyone", "members": [p[0] for p in _FAB_PEOPLE]}],
        "robot": {"home": "workshop"},
    }


@functools.cache
def fablab() -> Office:
    return parse_office(raw_fablab(), "fablab")


_COSTUME_PEOPLE = (
    ("ada", "Ada Quist", [{"type": "costume"}, {"type": "drawing"}]),
    ("bram", "Bram Dekker", [{"type": "costume"}, {"type": "drawing"}]),
    ("cleo", "Cleo Marin", [{"type": "costume"}]),
    ("dov", "Dov Adler", [{"type": "drawing"}]),
    ("esme", "Esme Lind", [{"type": "costume"}]),
    ("fitz", "Fitz Amari", [{"type": "drawing"}]),
)


def raw_costume_works() -> dict[str, Any]:
    return {
        "name": "costume_works",
        "locations": _places(
            [
                {"id": "shop_floor", "kind": "facility", "name": "Shop floor", "x": 4.0, "y": 20.5},
                {
                    "id": "wardrobe_room",
                    "kind": "facility",
                    "name": "Wardrobe room",
                    "x": 16.0,
                    "y": 20.5,
                },
            ]
        ),
        "item_types": [
            {"id": "costume", "name": "costume", "kind": "personal"},
            {"id": "drawing", "name": "drawing", "kind": "personal", "synonyms": ["drawings"]},
            {"id": "artwork", "name": "artwork", "kind": "electronic", "synonyms": ["file"]},
            {"id": "decal", "name": "vinyl decal", "kind": "product", "synonyms": ["decal"]},
            {"id": "plaque", "name": "engraved plaque", "kind": "product", "synonyms": ["plaque"]},
            {
                "id": "routed_panel",
                "name": "routed panel",
                "kind": "product",
                "synonyms": ["panel"],
            },
            {
                "id": "transfer",
                "name": "pressed transfer",
                "kind": "product",
                "synonyms": ["transfer"],
            },
            {"id": "scan", "name": "scan", "kind": "product", "synonyms": ["pdf"]},
        ],
        "operations": [
            {
                "id": "vinyl",
                "name": "vinyl cut",
                "verbs": ["vinyl cut", "vinyl-cut"],
                "input": "artwork",
                "product": "decal",
            },
            {
                "id": "engrave",
                "name": "laser engrave",
                "verbs": ["engrave", "laser engrave"],
                "input": "artwork",
                "product": "plaque",
            },
            {
                "id": "rout",
                "name": "rout",
                "verbs": ["rout", "mill", "cnc"],
                "input": "artwork",
                "product": "routed_panel",
            },
            {
                "id": "heatpress",
                "name": "heat press",
                "verbs": ["heat press", "heat-press"],
                "input": "artwork",
                "product": "transfer",
            },
            {"id": "steam", "name": "press", "verbs": ["press", "steam"], "input": "costume"},
            {
                "id": "scan",
                "name": "scan",
                "verbs": ["scan"],
                "input": "drawing",
                "product": "scan",
            },
        ],
        "people": _people(_COSTUME_PEOPLE, "artwork"),
        "facilities": [
            {
                "id": "vinyl_cutter",
                "name": "vinyl cutter",
                "location": "shop_floor",
                "operations": ["vinyl"],
                "guards": ["dov"],
                "products": ["decal"],
            },
            {
                "id": "laser_engraver",
                "name": "laser engraver",
                "location": "shop_floor",
                "operations": ["engrave"],
                "guards": ["dov"],
                "products": ["plaque"],
            },
            {
                "id": "cnc_router",
                "name": "CNC router",
                "location": "shop_floor",
                "operations": ["rout"],
                "guards": ["fitz"],
                "products": ["routed_panel"],
            },
            {
                "id": "heat_press",
                "name": "heat press",
                "location": "shop_floor",
                "operations": ["heatpress"],
                "guards": ["fitz"],
                "products": ["transfer"],
            },
            {
                "id": "wardrobe",
                "name": "wardrobe",
                "location": "wardrobe_room",
                "operations": ["steam"],
                "guards": ["esme"],
            },
            {
                "id": "scanner",
                "name": "scanner",
                "location": "shop_floor",
                "operations": ["scan"],
                "guards": ["dov"],
                "products": ["scan"],
            },
        ],
        "groups": [{"id": "all", "name": "Everyone", "members": [p[0] for p in _COSTUME_PEOPLE]}],
        "robot": {"home": "shop_floor"},
    }


@functools.cache
def costume_works() -> Office:
    return parse_office(raw_costume_works(), "costume_works")
