"""A county court's back office and its biobank annex for the reader's tests of blind rounds
43-48's classes (the rounds' offices and sentences were never read): the archive desk sends a
colleague's closed case papers to an off-site store (asking which store), the cold room ships
cryovials on dry ice to an outside lab (asking which lab), courtroom keys are held by the
ushers, and a colleague's surname (Kessel) is near a lab's name."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person("nia", "Nia Kessel", "case_papers", "cryovial", "stapler"),
    ob.person("omar", "Omar Fenwick", "case_papers", "courtroom_keys", "stapler"),
    ob.person("ruth", "Ruth Bridger", "case_papers", "cryovial"),
    ob.person("sam", "Sam Records", "case_papers", "courtroom_keys"),
    ob.person("tess", "Tess Hale", "case_papers", "stapler", "charger", "timesheet", "court_order"),
    ob.person(
        "vera", "Vera Lind", "courtroom_keys", "stapler", "timesheet", aliases=["Judge's Clerk"]
    ),
    ob.person("wyn", "Wyn Moss", "stapler", "timesheet", aliases=["Head of Department"]),
    ob.person("yara", "Yara Stone", "timesheet", aliases=["Director's PA", "practice manager"]),
)


def raw_county_court() -> dict[str, Any]:
    return ob.office_file(
        "county_court",
        _PEOPLE,
        rooms=[
            ob.room("archive_room", "Archive room", 4.0, 18.0),
            ob.room("cold_room", "Cold room", 12.0, 18.0),
            ob.room("court_3", "Court 3", 20.0, 18.0, kind="room"),
        ],
        item_types=[
            ob.item("stapler", "stapler"),
            ob.item("charger", "charger"),
            ob.item("timesheet", "timesheet", "personal", signable=True, synonyms=["form"]),
            ob.item("courtroom_keys", "courtroom keys", synonyms=["keys"]),
            ob.item("case_papers", "case papers", "personal", synonyms=["case file"]),
            ob.item("cryovial", "cryovials", "personal", synonyms=["cryovial"]),
            ob.item("court_order", "court order", "personal", synonyms=["order", "judgment"]),
            ob.item("copy", "photocopy", "product", synonyms=["copy"]),
            ob.item("certified_copy", "certified copy", "product", synonyms=["sealed copy"]),
        ],
        operations=[
            ob.operation(
                "archive",
                "archive",
                "send to the off-site archive",
                "send off-site",
                name="off-site archiving",
                input="case_papers",
                sends_out=True,
                destination_asked="which store",
            ),
            ob.operation(
                "ship",
                "ship",
                "send out on dry ice",
                name="dry ice shipping",
                input="cryovial",
                sends_out=True,
                destination_asked="which lab",
            ),
            ob.operation("photocopy", "photocopy", "copy", input="court_order", product="copy"),
            ob.operation("certify", "certify", input="court_order", product="certified_copy"),
        ],
        facilities=[
            ob.facility(
                "copier",
                "copier",
                at="archive_room",
                guards=["omar"],
                operations=["photocopy", "certify"],
            ),
            ob.facility(
                "archive_desk",
                "archive desk",
                at="archive_room",
                guards=["omar"],
                operations=["archive"],
            ),
            ob.facility(
                "dry_ice_box", "dry ice box", at="cold_room", guards=["ruth"], operations=["ship"]
            ),
        ],
        home="archive_room",
        group=("court", "Court"),
    )


county_court = ob.parsed(raw_county_court)
