"""A noun compound with a time after a request ("can u bring them over, ground run in 10",
"..., print deadline at 5", "..., copy run at 3pm") names an event and when it is: why and by
when the request is wanted, context, never a service asked for; the request before it is
done. Before, a modifier glued to a service's verb ("ground run", "test print") was declined
as a service nobody offers ("Sorry, I can't ground run"), and the request with it
(screen/timed_event.py). A real service request with a time ("print my file in 10 minutes",
"run my sample at 3"), and the compound said alone, read as before."""

from __future__ import annotations

import pytest

from assistantx.core.task_schema import TaskFrame
from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import frame_reader
from helpers.vet_practice import vet_practice

# the vet practice runs samples on its gel rig: a service whose verb is "run"
_vet = frame_reader(vet_practice, "frank")
_default = frame_reader(default_office, "mao")
_harbour = frame_reader(harbour_office, "will")


def _read(office: str, text: str) -> TaskFrame:
    return {"vet": _vet, "default": _default, "harbour": _harbour}[office](text)


@pytest.mark.parametrize(
    ("office", "text", "item", "owner"),
    [
        # the class's analogue, in an office whose service verb is "run"
        (
            "vet",
            "hazel has a stethoscope right? can u bring it over, ground run in 10",
            "stethoscope",
            "hazel",
        ),
        ("vet", "can u bring me a thermometer, ground run in 10", "thermometer", None),
        ("vet", "can u bring me a thermometer, gel run at 3pm", "thermometer", None),
        ("vet", "can u bring me a thermometer. test run at half two", "thermometer", None),
        # the default office's own verbs: print, copy
        ("default", "can u bring me a stapler, test print in 5", "stapler", None),
        (
            "default",
            "zhang has a stapler right? can u bring it over, copy run at 3pm",
            "stapler",
            "zhang",
        ),
        ("default", "can u bring me scissors, print deadline at 5", "scissors", None),
        # harbour's verbs: scan, post (frank)
        (
            "harbour",
            "max has an umbrella right? can u bring it over, ground run in 10",
            "umbrella",
            "max",
        ),
        ("harbour", "can u bring me a ruler, test scan in 5 mins", "ruler", None),
        ("harbour", "can you bring me a calculator, bulk post at 4pm", "calculator", None),
    ],
)
def test_the_request_is_done_and_the_event_is_context(
    office: str, text: str, item: str, owner: str | None
) -> None:
    frame = _read(office, text)
    assert frame.question is None and frame.decline is None, (frame.question, frame.decline)
    assert [(t.kind, t.item, t.owner) for t in frame.tasks] == [("transfer", item, owner)]


@pytest.mark.parametrize(
    ("office", "text", "kind"),
    [
        ("default", "print my file in 10 minutes", "print"),
        ("vet", "can you run my sample in 10 minutes", "heat"),  # the run service's task kind
        ("vet", "run my sample through the gel rig", "heat"),
    ],
)
def test_a_service_asked_with_a_time_is_still_asked(office: str, text: str, kind: str) -> None:
    frame = _read(office, text)
    assert [t.kind for t in frame.tasks] == [kind]


@pytest.mark.parametrize(
    ("office", "text", "kinds"),
    [
        # an object ("my sample"), not an event's name: both are done
        ("vet", "bring me a thermometer, then run my sample at 3", ["transfer", "heat"]),
        ("default", "bring me a stapler, print my file in 10 minutes", ["transfer", "print"]),
    ],
)
def test_a_second_request_with_a_time_is_no_event(office: str, text: str, kinds: list[str]) -> None:
    frame = _read(office, text)
    assert [t.kind for t in frame.tasks] == kinds


@pytest.mark.parametrize(
    ("office", "text", "said"),
    [
        ("default", "ground print in 5", "ground print"),  # no request before: as before
        ("default", "bring me a stapler and laser print my file", "laser print"),
    ],
)
def test_a_modified_service_asked_is_still_declined(office: str, text: str, said: str) -> None:
    frame = _read(office, text)
    assert frame.tasks == [] and frame.decline is not None and said in frame.decline
