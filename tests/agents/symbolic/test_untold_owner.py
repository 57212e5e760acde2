"""A request for a colleague's thing that says the owner need not be told ("grab Wang's seal
while she's out, no need to tell her", "borrow Zhang's charger, you don't need to tell her",
"just take it, he won't need to know") takes it without the owner's knowledge: declined in
words, saying their own yes is needed (class 63f-1: the owner was asked and, on her yes, the
seal was handed over). Telling the speaker ("no need to tell me when it's done") and a thing
of nobody's or the speaker's own are read as before."""

from __future__ import annotations

import pytest
from _offices import parser


def _frame(text: str, who: str = "chen"):  # type: ignore[no-untyped-def]
    return parser("default").parse(text, who)


@pytest.mark.parametrize(
    "text",
    [
        "grab Wang Fang's seal while she's out, no need to tell her",
        "take Lee's stapler, no need to tell him",
        "borrow Zhang's charger, you don't need to tell her",
        "just take Lee's stapler, he won't need to know",
        "could you get me Yang Lei's stapler? she doesn't need to know",
        "take Lee's stapler to Zhang, no need to let him know",
        "bring me Wang's stapler, you dont have to tell her",
    ],
)
def test_a_colleagues_thing_taken_untold_is_declined(text: str) -> None:
    frame = _frame(text)
    assert frame.tasks == [] and frame.question is None, frame
    assert frame.decline is not None and "own yes" in frame.decline, frame


@pytest.mark.parametrize(
    ("text", "task"),
    [
        ("take my stapler to Lee, no need to tell me", ("transfer", "chen", "lee")),
        ("bring Lee my stapler, no need to let me know", ("transfer", "chen", "lee")),
        ("bring me a pen from the cupboard, no need to ask anyone", ("transfer", None, "chen")),
        ("bring me Lee's stapler", ("transfer", "lee", "chen")),
    ],
)
def test_telling_the_speaker_or_nobodys_thing_is_read_as_before(
    text: str, task: tuple[str, str | None, str]
) -> None:
    frame = _frame(text)
    assert frame.decline is None, frame
    assert [(t.kind, t.owner, t.recipient) for t in frame.tasks] == [task], frame
