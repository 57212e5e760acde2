"""A message with no request left: the replies of its pieces, one "Shall I ...?" for a question
that may be a request, and what is only an aside."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.answer import answered, aside
from assistantx.agents.symbolic.reading.screen.findings import Finding, Screened
from assistantx.agents.symbolic.reading.screen.terms import Terms
from reading.screen._judge import Read


def test_the_replies_are_joined_and_nothing_is_done(message: Read) -> None:
    msg = message("thanks. Wang is away")
    live = [
        Finding("thanks", msg.pieces[0], "thanks", message="You're welcome!"),
        Finding("fact", msg.pieces[1], "a fact: Wang Fang is away"),
    ]
    out = answered(Screened(text=msg.text), live, withdrawn=False)
    assert out.decline == "You're welcome! Thanks, noted: Wang Fang is away. I did nothing."
    assert out.outcome == "done"


def test_one_offer_is_asked_as_shall_i(message: Read) -> None:
    msg = message("does anyone have a pen?")
    offer = Finding(
        "question",
        msg.pieces[0],
        "a question",
        message="Wang has one.",
        offer="bring me a pen",
        shall="Shall I bring you one?",
    )
    out = answered(Screened(text=msg.text), [offer], withdrawn=False)
    assert (out.question, out.offer, out.decline) == (
        "Wang has one. Shall I bring you one?",
        "bring me a pen",
        None,
    )


def test_a_withdrawal_says_the_request_is_dropped(message: Read) -> None:
    msg = message("never mind")
    live = [Finding("withdrawn", msg.pieces[0], "withdraws the request")]
    out = answered(Screened(text=msg.text), live, withdrawn=True)
    assert out.decline == "OK, I've dropped that request. I did nothing."


def test_words_beside_thanks_that_name_nothing_are_an_aside(terms: Terms, message: Read) -> None:
    msg = message("thanks, lifesaver")
    live = [Finding("thanks", msg.pieces[0], "thanks")]
    assert aside(terms, "lifesaver", live, [msg.pieces[1]])
    assert not aside(terms, "bring me a pen", live, [msg.pieces[1]])
    assert not aside(terms, "lifesaver", [], [msg.pieces[1]])  # nothing beside it
