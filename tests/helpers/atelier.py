"""A small fashion atelier for the reader's tests of service chains on a paper the requester
holds, a plot of a file whose content is described, and clipped participles ("signd"): a
signable spec sheet everyone holds (also called a "tech pack"), an electronic pattern file
plotted full size on a plotter, a copier that photocopies a spec sheet, and a walkie-talkie
one colleague keeps."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("mara", "Mara Quint"),
    ob.person("priya", "Priya Nair"),
    ob.person("zeynep", "Zeynep Arslan"),
    ob.person("tomas", "Tomas Ruiz"),
    ob.person("ines", "Ines Vidal"),
    ob.person("chase", "Chase Boyd", "walkie"),
    ob.person("frank", "Frank Odell"),
)


def raw_atelier() -> dict[str, Any]:
    return ob.office_file(
        "atelier",
        _PEOPLE,
        rooms=[
            ob.room("cutting_room", "Cutting room", 4.0, 20.0),
            ob.room("copy_room", "Copy room", 12.0, 20.0),
        ],
        item_types=[
            ob.item("spec_sheet", "spec sheet", "personal", signable=True, synonyms=["tech pack"]),
            ob.item("pattern_file", "pattern file", "electronic", synonyms=["file"]),
            ob.item("walkie", "walkie-talkie", synonyms=["radio", "walkie"]),
            ob.item("pattern_plot", "pattern plot", "product", synonyms=["plot", "pattern"]),
            ob.item("copy", "photocopy", "product", synonyms=["copy"]),
        ],
        operations=[
            ob.operation("plot", "plot", input="pattern_file", product="pattern_plot"),
            ob.operation("copy", "copy", "photocopy", input="spec_sheet", product="copy"),
        ],
        facilities=[
            ob.facility(
                "plotter", "plotter", at="cutting_room", guards=["tomas"], operations=["plot"]
            ),
            ob.facility("copier", "copier", at="copy_room", guards=["ines"], operations=["copy"]),
        ],
        everyone_owns=["spec_sheet", "pattern_file"],
        home="cutting_room",
    )


atelier = ob.parsed(raw_atelier)
