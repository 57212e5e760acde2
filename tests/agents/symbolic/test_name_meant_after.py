"""A name made clear after the request, and a name that is also the speaker's own surname
(blind round 59-60 class 4; the round's own offices and sentences were never read): Tilly
Grant asks "could Grant lend me his drill? Grant Okoro I mean, not me lol". The full name
said before "I mean", or before "not me", in a sentence of its own is the same correction as
"I mean Grant Okoro": it names whom the name in the request meant (the lender), and "lend
me" keeps the speaker as the one who gets the drill. A name that is the speaker's surname,
said as the one asked to lend, is the colleague whose given name it is."""

from __future__ import annotations

import pytest

from helpers.lending_bench import lending_bench
from helpers.reading import frame_reader

_frame = frame_reader(lending_bench, "tilly")


@pytest.mark.parametrize(
    "text",
    [
        "Sorry to be a pain - could Grant lend me his drill? Grant Okoro I mean, not me lol",
        "could Grant lend me his drill? Grant Okoro I mean",
        "could Grant lend me his drill? Grant Okoro, not me",
        "could Grant lend me his drill? Grant Okoro not me haha",
        "could Grant lend me his drill? I mean Grant Okoro, not me lol",
        "can Grant lend me his drill for an hour? Okoro I mean",
        "could Grant lend me his drill?? (Grant Okoro I mean, not me)",
        "could Grant lend me his drill - Grant Okoro, not me lol",
        "could grant lend me her drill? grant okoro i mean",
        "could Grant lend me his drill?",
    ],
)
def test_the_lender_meant_and_the_speaker_gets_it(text: str) -> None:
    frame = _frame(text)
    assert [(t.item, t.owner, t.recipient, t.source) for t in frame.tasks] == [
        ("drill", "grant", "tilly", None)
    ], frame


@pytest.mark.parametrize(
    ("text", "who"),
    [
        ("take my lamp to Grant. Grant Okoro I mean", "grant"),
        ("take my lamp to Bea, not Jory", "bea"),
        ("take my lamp to Bea", "bea"),
    ],
)
def test_a_recipient_said_plainly_keeps_its_reading(text: str, who: str) -> None:
    frame = _frame(text, "mira")
    assert [(t.item, t.owner, t.recipient) for t in frame.tasks] == [("lamp", "mira", who)], frame


def test_the_name_of_two_people_is_the_given_name_colleague() -> None:
    # Grant Okoro's given name, Tilly Grant's family name: his (``given_name_meant``)
    frame = _frame("take my lamp to Grant", "mira")
    assert frame.question is None, frame
    assert [t.recipient for t in frame.tasks] == ["grant"], frame
