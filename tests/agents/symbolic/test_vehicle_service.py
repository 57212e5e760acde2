"""A send-out service named after its vehicle ("send out on the van"): "send my signed
contract out on the van to Fairfield Farm" asks for that service, with the farm as where it
goes. The words "on the van" had been read as a place outside the office, and the request
declined. A vehicle that names no service ("bring my contract to the van") is still declined,
and a colleague is still a delivery."""

from __future__ import annotations

import pytest
from _gear_office import _raw, read_as_lee

from helpers.office_builder import parsed
from helpers.reading import frame_reader


def test_a_service_said_by_its_vehicle_is_run() -> None:
    frame = read_as_lee("Send my signed contract out on the van to Fairfield Farm")
    assert frame.decline is None and frame.question is None, frame
    assert [(t.operation, t.item, t.owner) for t in frame.tasks] == [
        ("dispatch", "contract", "lee")
    ], frame


def test_a_vehicle_that_names_no_service_is_declined() -> None:
    frame = read_as_lee("bring my contract to the van")
    assert frame.tasks == [], frame
    assert frame.decline is not None and "outside the office" in frame.decline, frame


def test_sent_to_a_colleague_is_a_delivery() -> None:
    frame = read_as_lee("send my contract to Zhang")
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("transfer", "contract", "zhang")
    ], frame


def _noted_raw() -> dict[str, object]:
    """The gear office with its contract also called a "delivery note"."""
    raw = _raw()
    for row in raw["item_types"]:  # type: ignore[attr-defined]
        if row["id"] == "contract":
            row["synonyms"] = ["delivery note"]
    return raw


_read_noted = frame_reader(parsed(_noted_raw), "lee")


@pytest.mark.parametrize(
    "text",
    [
        "send my delivery note out on the van please",
        "send my contract out on the van please",
        "send my signed contract out",
    ],
)
def test_a_send_out_with_its_particle_after_the_object_asks_where(text: str) -> None:
    """Fix213a class 6: "send my X out ..." (the particle after the object) is the send-out
    service, as "send out my X" is: where it goes is asked, never what "the van" means."""
    asked = _read_noted(text).question
    assert asked == _read_noted("send out my contract").question, asked
    assert asked is not None and asked.startswith("Where should I dispatch it to?"), asked


def test_a_colleague_after_the_split_particle_is_asked_about_as_before() -> None:
    assert (
        read_as_lee("send my contract out to Zhang").question
        == read_as_lee("send out my contract to Zhang").question
    )
