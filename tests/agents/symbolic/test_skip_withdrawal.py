""" "skip it", "skip that", "just skip it": the verb "skip" with the pronoun of what was asked
(or an article: "skip the ruler") withdraws it, as "forget it" does: answered in words,
nothing moves, never "I'm not sure what you need". In every office, also where a colleague is
called Skip ("Skip needs my file" stays a need of Skip's)."""

from __future__ import annotations

import pytest

from helpers.dataset_offices import default_office, harbour_office
from helpers.reading import OfficeOf, frame_reader
from helpers.renamed_offices import harbour_with_skip

_OFFICES = [(harbour_with_skip, "may"), (harbour_office, "may"), (default_office, "lee")]


@pytest.mark.parametrize(("office", "who"), _OFFICES)
@pytest.mark.parametrize(
    "text",
    [
        "skip it, I'll walk over myself",  # the class
        "skip that",
        "skip it, never mind",
        "Skip it, I'll take it over myself later",
        "just skip it",
        "nah skip that one",
        "skip this, I found one",
    ],
)
def test_skip_with_the_errands_pronoun_withdraws(office: OfficeOf, who: str, text: str) -> None:
    frame = frame_reader(office, who)(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and "dropped" in frame.decline, frame


@pytest.mark.parametrize("text", ["ok just forget it", "just never mind"])
def test_just_before_a_withdrawal_still_withdraws(text: str) -> None:
    frame = frame_reader(harbour_office, "may")(text)
    assert frame.tasks == [] and frame.decline is not None and "dropped" in frame.decline, frame


def test_a_colleague_called_skip_is_no_withdrawal() -> None:
    frame = frame_reader(harbour_with_skip, "may")("Skip needs my file")
    assert frame.decline is None and frame.question == "Shall I pass your file to Skip Larsen?"


def test_a_request_after_skip_as_a_name_is_read() -> None:
    frame = frame_reader(harbour_with_skip, "may")("Skip's waiting on it, send him my file")
    assert frame.question is None, frame
    assert [(t.kind, t.recipient) for t in frame.tasks] == [("send_file", "bill")]
