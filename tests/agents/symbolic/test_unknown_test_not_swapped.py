"""A test or instrument the office does not have, asked for with a verb that names no work of
its own ("run an NMR on my crude product" where the only analysis is an IR spectrometer run
with "run"), is declined, saying what the office's machines do: never the office's one service
picked by the generic verb alone and run instead (round 59, class 1). The office's own names,
plain English nouns, particles and plain instruments read as before."""

from __future__ import annotations

from typing import Any

import pytest

from assistantx.core.office import load_office
from helpers.dataset_offices import harbour_office
from helpers.reading import frame_reader
from helpers.spectro_lab import spectro_lab

_lab = frame_reader(spectro_lab, "lee")
_lee = frame_reader(load_office, "lee")
_may = frame_reader(harbour_office, "may")


@pytest.mark.parametrize(
    ("read", "text", "named", "has"),
    [
        (_lab, "run an NMR on my crude product pls", "NMR", "spectrometer can IR scan"),
        (_lab, "could you run an nmr on my sample please", "nmr", "spectrometer can IR scan"),
        (_lab, "run a mass spec on my sample", "mass spec", "spectrometer can IR scan"),
        (_lab, "can you do a CT scan of my sample", "CT scan", "centrifuge can spin down"),
        (_lab, "get my sample through the PCR", "PCR", "spectrometer can IR scan"),
        (_lab, "get my blood sample through the PCR", "PCR", "centrifuge can spin down"),
        (_may, "can you do a CT scan of my document", "CT scan", "scanner can scan"),
        (_may, "do me an NMR on my document", "NMR", "scanner can scan"),
        (_lee, "run an MRI on my lunch", "MRI", "microwave can heat"),
    ],
)
def test_a_test_the_office_lacks_is_declined(read: Any, text: str, named: str, has: str) -> None:
    frame = read(text)
    assert not frame.tasks and frame.question is None, frame
    assert frame.decline is not None, frame
    assert f"no {named} here" in frame.decline and has in frame.decline, frame


@pytest.mark.parametrize(
    ("read", "text", "kind"),
    [
        (_lab, "run an IR on my sample", "heat"),
        (_lab, "run my sample on the IR", "heat"),
        (_lab, "can you run my sample", "heat"),
        (_lab, "run a check on my sample", "heat"),
        (_lab, "do a print of my file", "print"),
        (_lee, "run off 3 copies of my document", "copy"),
        (_lee, "do a print of my file", "print"),
        (_may, "do a scan of my document", "copy"),
        (_lab, "laminate my banner", "heat"),
    ],
)
def test_the_offices_own_work_is_unchanged(read: Any, text: str, kind: str) -> None:
    frame = read(text)
    assert frame.decline is None and frame.question is None, frame
    assert [t.kind for t in frame.tasks] == [kind], frame


@pytest.mark.parametrize("read", [_lee, _lab])
def test_a_made_thing_after_do_me_is_unchanged(read: Any) -> None:
    frame = read("do me a coffee")
    assert frame.decline is None and frame.question is None, frame
    assert [t.item for t in frame.tasks] == ["coffee"], frame


@pytest.mark.parametrize(
    "text",
    [
        "can u get my sample sorted before the customer comes in at 3",
        "can you run an OCT scan on mrs hughes for me",
    ],
)
def test_no_thing_worked_on_by_an_unknown_name_is_not_declined_so(text: str) -> None:
    frame = _lab(text)
    assert frame.decline is None or "there is no" not in frame.decline, frame
