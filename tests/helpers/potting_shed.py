"""A potting shed for the reader's tests of blind round 43's classes (the round's own offices
and sentences were never read): a tool store that keeps secateurs and folders, a compost heap
that takes prunings (an operation that consumes its item), a shredder for ledgers, a
laminator for posters, a recycling bin that takes drawing sets, and a trowel several people own."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("ivo", "Ivo Brandt", "trowel", "ledger", "poster", "prunings", "drawing"),
    ob.person("morwen", "Morwen Tate", "trowel", "ledger", "drawing", "prunings"),
    ob.person("pell", "Pell Osei", "ledger", "poster"),
    ob.person("rudd", "Rudd Keane", "trowel"),
)


def raw_potting_shed() -> dict[str, Any]:
    return ob.office_file(
        "potting shed",
        _PEOPLE,
        rooms=[
            ob.room("stores", "Tool store", 4.0, 20.0),
            ob.room("yard", "Yard", 20.0, 20.0),
        ],
        item_types=[
            ob.item("trowel", "trowel"),
            ob.item("ledger", "ledger", "personal"),
            ob.item("poster", "poster", "personal"),
            ob.item("drawing", "drawing set", "personal", synonyms=["drawings"]),
            ob.item("prunings", "bag of prunings", synonyms=["prunings"]),
            ob.item("secateurs", "secateurs", consumable=True, synonyms=["pruners"]),
            ob.item("folder", "folder", consumable=True, synonyms=["folders"]),
        ],
        operations=[
            ob.operation("compost", "compost", input="prunings", consumes=True),
            ob.operation("shred", "shred", input="ledger", consumes=True),
            ob.operation("laminate", "laminate", input="poster"),
            ob.operation("recycle", "recycle", input="drawing", consumes=True),
        ],
        facilities=[
            ob.facility(
                "tool_store",
                "tool store",
                at="stores",
                guards=["rudd"],
                supplies=["secateurs", "folder"],
            ),
            ob.facility(
                "compost_heap", "compost heap", at="yard", guards=["rudd"], operations=["compost"]
            ),
            ob.facility("shredder", "shredder", at="stores", guards=["pell"], operations=["shred"]),
            ob.facility(
                "laminator", "laminator", at="stores", guards=["pell"], operations=["laminate"]
            ),
            ob.facility(
                "recycling_bin", "recycling bin", at="yard", guards=["rudd"], operations=["recycle"]
            ),
        ],
        home="stores",
    )


potting_shed = ob.parsed(raw_potting_shed)
