"""A print room whose scan makes an electronic file (blind round 139's class 2; its own
office was never read): the room prints, photocopies, scans, laminates, binds and shreds a
form; its products are a printout, a photocopy and a scan, the scan a PDF sent by message (an
electronic item named "scan", the operation's own verb). Nadia owns a booking form."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("nadia", "Nadia Haddad", "form"),
    ob.person("omar", "Omar Said", "form"),
    ob.person("lucy", "Lucy Chen"),
    ob.person("raj", "Raj Mehta"),
)


def raw_scanning_room(*, scan_kind: str = "electronic") -> dict[str, Any]:
    """``scan_kind``: the scan's item kind (electronic: a PDF; product: a paper scan)."""
    return ob.office_file(
        "scanning room",
        _PEOPLE,
        rooms=[ob.room("print_room", "Print room", 12.0, 20.0)],
        item_types=[
            ob.item("form", "form", "personal", synonyms=["booking form"]),
            ob.item("printout", "printout", "product"),
            ob.item("photocopy", "photocopy", "product"),
            ob.item("scan", "scan", scan_kind, synonyms=["PDF"]),
        ],
        operations=[
            ob.operation("print", "print", input="form", product="printout"),
            ob.operation("copy", "copy", "photocopy", input="form", product="photocopy"),
            ob.operation("scan", "scan", input="form", product="scan", done="scanned to PDF"),
            ob.operation("laminate", "laminate", input="form"),
            ob.operation("bind", "bind", input="form"),
            ob.operation("shred", "shred", input="form", consumes=True),
        ],
        facilities=[
            ob.facility(
                "print_room",
                "print room",
                at="print_room",
                guards=["lucy", "raj"],
                operations=["print", "copy", "scan", "laminate", "bind", "shred"],
                products=["printout", "photocopy", "scan"],
            ),
        ],
        home="print_room",
    )


scanning_room = ob.parsed(raw_scanning_room)
paper_scanning_room = ob.parsed(lambda: raw_scanning_room(scan_kind="product"))
