"""A seed-testing lab for the reader's tests of places named like a service and of a
requester's own thing taken to a service (fix103d's classes; the measured offices and
sentences were never read): a drying cabinet in the drying room dries seed samples, a courier
desk in a room called "Dispatch" (also a verb of its courier service) sends papers out, a
bump-test station in the gas bay bump-tests gas monitors ("4-gas"), and a printer in the print
room prints; one colleague's moisture meter is kept in the drying cabinet, and several people
own a gas monitor each."""

from __future__ import annotations

from typing import Any

from helpers import office_builder as ob

_PEOPLE = (
    ob.person(
        "seun",
        "Seun Adeyemi",
        ob.kept("moisture_meter", at="drying_room", facility="drying_cabinet"),
        "gas_monitor",
    ),
    ob.person("mateus", "Mateus Costa", "moisture_meter"),
    ob.person("ines", "Ines Moreau", "pocket_balance", "gas_monitor", "seed_sample"),
    ob.person("olek", "Olek Nowak", "gas_monitor"),
    ob.person("rania", "Rania Haddad", "stapler"),
)


def raw_seed_lab() -> dict[str, Any]:
    return ob.office_file(
        "seed lab",
        _PEOPLE,
        rooms=[
            ob.room("drying_room", "Drying room", 4.0, 20.0),
            ob.room("dispatch", "Dispatch", 12.0, 20.0),
            ob.room("gas_bay", "Gas bay", 20.0, 20.0),
            ob.room("print_room", "Print room", 28.0, 20.0),
            ob.room("meeting_room", "Meeting room", 30.0, 12.0, kind="room"),
        ],
        item_types=[
            ob.item("moisture_meter", "moisture meter"),
            ob.item("pocket_balance", "pocket balance"),
            ob.item("gas_monitor", "gas monitor", synonyms=["4-gas"]),
            ob.item("seed_sample", "seed sample"),
            ob.item("stapler", "stapler"),
            ob.item("document", "document", "personal", synonyms=["contract", "form"]),
            ob.item("printout", "printout", "product"),
        ],
        operations=[
            ob.operation("dry", "dry", input="seed_sample"),
            ob.operation(
                "courier",
                "courier",
                "dispatch",
                name="send by courier",
                input="document",
                sends_out=True,
            ),
            ob.operation("bump_test", "bump test", input="gas_monitor"),
            ob.operation("print", "print", input="document", product="printout"),
        ],
        facilities=[
            ob.facility(
                "drying_cabinet",
                "drying cabinet",
                at="drying_room",
                guards=["rania"],
                operations=["dry"],
            ),
            ob.facility(
                "courier_desk",
                "courier desk",
                at="dispatch",
                guards=["rania"],
                operations=["courier"],
            ),
            ob.facility(
                "bump_station",
                "bump-test station",
                at="gas_bay",
                guards=["olek"],
                operations=["bump_test"],
            ),
            ob.facility(
                "printer",
                "printer",
                at="print_room",
                guards=["rania"],
                operations=["print"],
                products=["printout"],
            ),
        ],
        everyone_owns=["document"],
        home="dispatch",
    )


seed_lab = ob.parsed(raw_seed_lab)
