"""The colleague a request asks to look the requester's paper over and sign it ("Can Ingrid
have a look at my report and sign it?", blind round 50's class; its own sentences were never
read) is the one who signs: the look-over clause has no work of its own, and the "sign it"
after it took nobody as its doer, so the reader asked who should do it. The subject of a
statement ("Pim has my report") is still no doer."""

from __future__ import annotations

import pytest

from helpers.reading import frame_reader
from helpers.survey_hut import survey_hut

_frame = frame_reader(survey_hut, "okafor")


@pytest.mark.parametrize(
    ("text", "signer"),
    [
        ("Can Ingrid have a look at my report and sign it? Thanks!", "halvorsen"),
        ("could Dr Halvorsen check my contract and sign it", "halvorsen"),
        ("can ingrid look over my paperwork and sign it please", "halvorsen"),
        ("could Ruth read my report and sign it", "adeyemi"),
        ("would Miles mind reading my contract and signing it", "miles"),
        ("ask Pim to check my report and sign it", "pim"),
        # near-misses read as before: the signer named by the work itself
        ("can Ruth Adeyemi sign my paperwork when she gets a sec", "adeyemi"),
        ("could Miles sign my report", "miles"),
    ],
)
def test_the_one_asked_to_look_it_over_signs_it(text: str, signer: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.owner, t.recipient, t.actor) for t in frame.tasks] == [
        ("sign", "paper", "okafor", "okafor", signer)
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        "Pim has my report, sign it",
        "my report is on my desk, please sign it",
    ],
)
def test_a_statements_subject_is_no_signer(text: str) -> None:
    frame = _frame(text)
    assert not any(t.actor for t in frame.tasks), frame
