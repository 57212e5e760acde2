"""A request that has a colleague, named by title and surname, sign the requester's paper
called by a name the office does not list ("would you be so kind as to get Ms Adeyemi to sign
the sampling plan?", blind round 50's class; its own sentences were never read): the paper is
the requester's one signable paper, and "would you be so kind as to <task>" is a request, not
a question about where the signer sits. A question stays a question."""

from __future__ import annotations

import pytest

from helpers.reading import frame_reader
from helpers.survey_hut import survey_hut

_frame = frame_reader(survey_hut, "okafor")


@pytest.mark.parametrize(
    ("text", "signer"),
    [
        ("Would you be so kind as to get Ms Adeyemi to sign the sampling plan?", "adeyemi"),
        ("could you get Dr Halvorsen to sign off the risk assessment", "halvorsen"),
        ("get Miles to countersign the rota", "miles"),
        ("please get Ms Adeyemi to sign the plan", "adeyemi"),
        ("would you be good enough to get Dr Halvorsen to sign this risk assessment", "halvorsen"),
        # near-misses read as before: the office's own name of the paper, "my <word>"
        ("get Ms Adeyemi to sign my paperwork", "adeyemi"),
        ("could you get Miles to sign my plan", "miles"),
    ],
)
def test_an_unlisted_paper_to_sign_is_the_requesters(text: str, signer: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item, t.owner, t.recipient, t.actor) for t in frame.tasks] == [
        ("sign", "paper", "okafor", "okafor", signer)
    ], frame


@pytest.mark.parametrize(
    "text",
    [
        "Where is Ms Adeyemi?",
        "will Miles be in tomorrow?",
        "would you be so kind as to tell me where Ms Adeyemi sits?",
    ],
)
def test_a_question_about_the_signer_stays_a_question(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.decline is not None, frame
    assert "works at" in frame.decline, frame


def test_two_unlisted_papers_still_ask_which() -> None:
    frame = _frame("get Miles to sign the rota and the plan")
    assert frame.tasks == [] and frame.question is not None, frame


def test_gracious_wording_of_an_errand_is_a_request() -> None:
    frame = _frame("would you be kind enough to bring me Miles's clipboard?")
    assert [(t.kind, t.item, t.owner, t.recipient) for t in frame.tasks] == [
        ("transfer", "clipboard", "miles", "okafor")
    ], frame
