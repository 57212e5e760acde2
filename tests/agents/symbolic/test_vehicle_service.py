"""A send-out service named after its vehicle ("send out on the van"): "send my signed
contract out on the van to Fairfield Farm" asks for that service, with the farm as where it
goes. The words "on the van" had been read as a place outside the office, and the request
declined. A vehicle that names no service ("bring my contract to the van") is still declined,
and a colleague is still a delivery."""

from __future__ import annotations

from _gear_office import read_as_lee


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
