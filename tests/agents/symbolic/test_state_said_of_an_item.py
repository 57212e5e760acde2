""" "anyone got a torque wrench going spare?" where the office also calls its spare key a
"spare" (blind round 24's class): the word says the wrench's state, it is no second item, so
the ask borrows a wrench for the speaker; on main it asked what to do with the spare key."""

from __future__ import annotations

import pytest

from assistantx.core.office import Office
from helpers import office_builder as ob
from helpers.reading import frame_reader


def _workshop() -> Office:
    return ob.parsed(
        lambda: ob.office_file(
            "workshop",
            (
                ob.person("ines", "Ines Varga"),
                ob.person("otto", "Otto Brandt", "torque_wrench", "car_key"),
                ob.person("maud", "Maud Fairley", "torque_wrench"),
            ),
            rooms=[ob.room("bay", "Service bay", 4.0, 20.0)],
            item_types=[
                ob.item("torque_wrench", "torque wrench"),
                ob.item("car_key", "car key"),
                ob.item("spare_key", "spare key", "product", synonyms=["spare"]),
                ob.item("plate", "number plate", "product", synonyms=["plates", "reg plates"]),
                ob.item("job_sheet", "job sheet", "personal"),
            ],
            operations=[
                ob.operation("cut", "cut", input="car_key", product="spare_key"),
                ob.operation("plates", "press", name="make up number plates", product="plate"),
            ],
            facilities=[
                ob.facility(
                    "key_machine",
                    "key machine",
                    at="bay",
                    guards=["maud"],
                    operations=["cut"],
                    products=["spare_key"],
                ),
                ob.facility(
                    "plate_press",
                    "plate press",
                    at="bay",
                    guards=["maud"],
                    operations=["plates"],
                    products=["plate"],
                ),
            ],
            home="bay",
        )
    )()


_frame = frame_reader(_workshop, "ines")


@pytest.mark.parametrize(
    "text",
    [
        "anyone got a torque wrench going spare? mine's off being calibrated till thurs",
        "anyone got a torque wrench spare? need to do the wheels",
    ],
)
def test_the_state_is_said_of_the_thing_asked_for(text: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("transfer", "torque_wrench", "ines")
    ], frame


def test_the_spare_is_still_the_product_where_it_is_the_thing() -> None:
    frame = _frame("can you get me a spare cut from my car key")
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("copy", "car_key", "ines")]


def test_a_state_told_of_a_word_that_only_leads_a_name_is_context() -> None:
    """ "reg is on the job sheet" where "reg plates" is a name of the plates (blind round
    24's class): told, context beside the request; on main it was read as part of it and
    the assistant asked whose job sheet."""
    frame = _frame("need some plates pressing for the van, reg is on the job sheet")
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [("produce", "plate", "ines")]
