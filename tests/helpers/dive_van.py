"""A dive team's van and workshop (fixer 201c's small office): colleagues at numbered benches,
things with long names and purposes (a "probe thermometer" to check temperatures, a multimeter
to measure voltage), a workshop that services regulators and a compressor that fills
cylinders, and colleagues whose surnames are English words (Harriet Cox, Ruth Mason)."""

from __future__ import annotations

from helpers import office_builder as ob
from helpers.office_builder import Row


def raw_dive_van() -> Row:
    people = (
        ob.person("lee", "Lee Park", "set_square", "regulator"),
        ob.person("harriet", "Harriet Cox", "cox_box", "multimeter"),
        ob.person("eoin", "Eoin Byrne", "set_square"),
        ob.person("ruth", "Ruth Mason", "probe_thermometer"),
        ob.person("dara", "Dara Quinn", "multimeter", "set_square"),
    )
    return ob.office_file(
        "dive van",
        people,
        rooms=[
            ob.room("workshop", "Workshop", 4.0, 20.0),
            ob.room("compressor_room", "Compressor room", 12.0, 20.0),
            ob.room("yard", "Yard", 20.0, 20.0, kind="room"),
        ],
        item_types=[
            {
                "id": "probe_thermometer",
                "name": "probe thermometer",
                "purposes": ["check temperatures"],
            },
            {"id": "multimeter", "name": "multimeter", "purposes": ["measure voltage"]},
            {"id": "regulator", "name": "regulator"},
            {"id": "cylinder", "name": "cylinder", "synonyms": ["tank"]},
            {"id": "cox_box", "name": "cox box"},
            {"id": "set_square", "name": "set square", "synonyms": ["square"]},
        ],
        operations=[
            ob.operation("service", "service", input="regulator"),
            ob.operation("fill", "fill", input="cylinder"),
        ],
        facilities=[
            ob.facility(
                "workshop_bench",
                "workshop",
                at="workshop",
                guards=["dara"],
                operations=["service"],
            ),
            ob.facility(
                "compressor",
                "compressor",
                at="compressor_room",
                guards=["dara"],
                operations=["fill"],
            ),
        ],
        home="yard",
        desk_word="bench",
    )


dive_van = ob.parsed(raw_dive_van)
