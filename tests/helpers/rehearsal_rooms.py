"""Two offices whose electronic file type is not called ``file``, for the tests of issue 23's
dataset tools (an outside writer's new office crashed ``dataset generate``).

- ``rehearsal_rooms``: a theatre's rehearsal rooms. Everyone's electronic ``script`` (the
  office's only file-like type) is made up into a rehearsal script pack at the photocopier,
  whose keepers are Ines and Tomas (Ines also asks for packs: a requester who is a keeper);
  the green-room urn makes tea; a prop cupboard keeps gaffer tape for anyone; contracts are
  signed by a colleague.
- ``drafting_studio``: an architects' studio. Everyone's ``drawing`` (the electronic type) is
  plotted at the plotter, kept by Mira and Oskar; there is no other file type either.
"""

from __future__ import annotations

from typing import Any

from assistantx.core.office import Office, parse_office
from helpers import office_builder as ob

_REHEARSAL_PEOPLE = (
    ob.person("ines", "Ines Carvalho", "torch", "contract"),
    ob.person("tomas", "Tomas Weller", "contract"),
    ob.person("priya", "Priya Raman", "torch", "contract"),
    ob.person("bruno", "Bruno Aalto", "stopwatch", "contract"),
    ob.person("hedda", "Hedda Moreau", "stopwatch", "contract"),
    ob.person("kwesi", "Kwesi Boateng", "contract"),
)


def raw_rehearsal_rooms() -> dict[str, Any]:
    return ob.office_file(
        "rehearsal_rooms",
        _REHEARSAL_PEOPLE,
        everyone_owns=["script"],
        desks=ob.desk_row(len(_REHEARSAL_PEOPLE), x0=4.0, y=5.0),
        rooms=[
            ob.room("copy_corner", "Copy corner", 6.0, 18.0),
            ob.room("green_room", "Green room", 18.0, 18.0),
        ],
        item_types=[
            ob.item("torch", "torch", synonyms=["flashlight"]),
            ob.item("stopwatch", "stopwatch"),
            ob.item("gaffer_tape", "gaffer tape", consumable=True, mass=True),
            ob.item("contract", "contract", "personal", signable=True),
            ob.item("script", "script", "electronic"),
            ob.item("script_pack", "rehearsal script pack", "product", synonyms=["script pack"]),
            ob.item("tea", "tea", "product"),
        ],
        operations=[
            ob.operation(
                "make_pack", "make up", name="make up", input="script", product="script_pack"
            ),
            ob.operation("brew", "brew", name="make tea", product="tea"),
        ],
        facilities=[
            ob.facility(
                "photocopier",
                "photocopier",
                at="copy_corner",
                guards=["ines", "tomas"],
                operations=["make_pack"],
                products=["script_pack"],
            ),
            ob.facility(
                "urn",
                "tea urn",
                at="green_room",
                guards=["hedda"],
                operations=["brew"],
                products=["tea"],
            ),
            ob.facility(
                "prop_cupboard",
                "prop cupboard",
                at="green_room",
                guards=["hedda"],
                supplies=["gaffer_tape"],
            ),
        ],
        home="copy_corner",
        group=("company", "Company"),
    )


rehearsal_rooms = ob.parsed(raw_rehearsal_rooms)


def rehearsal_rooms_without_files() -> Office:
    """The rehearsal rooms with no electronic file type at all: no scripts, so no script
    packs and no photocopier that makes them up."""
    raw = raw_rehearsal_rooms()
    raw["item_types"] = [t for t in raw["item_types"] if t["id"] not in ("script", "script_pack")]
    raw["operations"] = [o for o in raw["operations"] if o["id"] != "make_pack"]
    raw["facilities"] = [f for f in raw["facilities"] if f["id"] != "photocopier"]
    for person in raw["people"]:
        person["owns"] = [o for o in person["owns"] if o["type"] != "script"]
    return parse_office(raw, "no_files")


_DRAFTING_PEOPLE = tuple(
    ob.person(person_id, name, "scale_rule", "drawing")
    for person_id, name in (
        ("mira", "Mira Castell"),
        ("oskar", "Oskar Lind"),
        ("femi", "Femi Adeyemi"),
        ("greta", "Greta Holm"),
        ("yusuf", "Yusuf Demir"),
    )
)


def raw_drafting_studio() -> dict[str, Any]:
    return ob.office_file(
        "drafting_studio",
        _DRAFTING_PEOPLE,
        desks=ob.desk_row(len(_DRAFTING_PEOPLE), x0=5.0, step=5.0, y=4.0),
        rooms=[ob.room("plot_room", "Plot room", 12.0, 16.0)],
        item_types=[
            ob.item("scale_rule", "scale rule"),
            ob.item("drawing", "drawing", "electronic", synonyms=["cad file"]),
            ob.item("plot", "plot", "product", synonyms=["large print"]),
        ],
        operations=[ob.operation("plot", "plot", input="drawing", product="plot")],
        facilities=[
            ob.facility(
                "plotter",
                "plotter",
                at="plot_room",
                guards=["mira", "oskar"],
                operations=["plot"],
                products=["plot"],
            ),
        ],
        home="plot_room",
        group=("studio", "Studio"),
    )


drafting_studio = ob.parsed(raw_drafting_studio)
