"""A small studio where two colleagues share each given name (two Léas, two Sams), for the
reader's tests of a possessive given name that is shared (the lexicon's ``_settled_by_owner``
and ``given_name_meant``): which of them owns the thing is known of one only for some things,
of neither for others, and a thing a namesake owns that the assistant does not know of
(``known: false``) must never choose between them. No sentence or name of a measured office
is in it."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob


def _unknown(type_id: str) -> dict[str, Any]:
    return {"type": type_id, "known": False}


_PEOPLE = (
    ob.person("lea_f", "Léa Fournier", "mug", aliases=["Léa"]),
    ob.person("lea_k", "Léa Kaczmarek", _unknown("scale_rule"), "mug", aliases=["Léa"]),
    ob.person("sam_o", "Sam Ortiz", "ruler", "tape_measure", aliases=["Sam"]),
    ob.person("sam_b", "Sam Birch", "tape_measure", _unknown("stapler"), aliases=["Sam"]),
    ob.person("noor", "Noor Haddad", "ruler", "stapler"),
    ob.person("ivo", "Ivo Kaczmarek", "stapler"),
)


def raw_namesake_studio() -> dict[str, Any]:
    return ob.office_file(
        "namesake studio",
        _PEOPLE,
        rooms=[ob.room("studio", "Studio", 4.0, 20.0)],
        item_types=[
            ob.item("scale_rule", "scale rule"),
            ob.item("ruler", "ruler"),
            ob.item("tape_measure", "tape measure"),
            ob.item("stapler", "stapler"),
            ob.item("mug", "mug"),
        ],
        operations=[],
        facilities=[],
        home="studio",
    )


namesake_studio = ob.parsed(raw_namesake_studio)
