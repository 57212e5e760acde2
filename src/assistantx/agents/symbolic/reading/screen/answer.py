"""A message with no request left: the replies of its pieces in words, one "Shall I ...?"
for a question that may be a request, and what counts as an aside beside a thanks or a wish."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.curious import CURIOUS
from assistantx.agents.symbolic.reading.screen.english import split_words
from assistantx.agents.symbolic.reading.screen.findings import SAYS_NOTHING_TO_DO, Finding, Screened
from assistantx.agents.symbolic.reading.screen.pieces import Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import language


def aside(
    terms: Terms, left: str, live: list[Finding], kept: list[Piece], *, withdrawn: bool = False
) -> bool:
    """What is left beside a thanks, wish or withdrawal, or after a note, condition or
    report, names nothing of this office and asks for nothing ("..., lifesaver", "...,
    all sorted"): an aside, not a request. Before a report it is no closing remark
    ("hello there. I don't know more than I wrote" still says nothing of what is needed).
    ``withdrawn``: the message withdrew something; the withdrawal itself is no live verdict
    (what counts begins after it), yet what follows it and names nothing ("forget about the
    biscuits, not hungry anymore") is its reason, not a request to ask about."""
    anywhere = withdrawn or any(f.verdict in ("thanks", "wish", "withdrawn") for f in live)
    reports = [f.piece.start for f in live if f.verdict in SAYS_NOTHING_TO_DO]
    closing = bool(reports) and all(p.start > min(reports) for p in kept)
    if not (anywhere or closing):
        return False
    words = split_words(left)
    # "machine in the laundry": a function word of a longer name names nothing alone
    named = {w for w in _unpaired(words) if not language.is_function_word(w)}
    if named & terms.office_words or terms.acts.request(words):
        return False
    # "something longer?", "another one": what a statement beside it makes a request of
    helpers = {w for p in (*terms.en.purpose_heads, *terms.en.another_one) for w in split_words(p)}
    return not set(words) & helpers


def _unpaired(words: list[str]) -> list[str]:
    """The words without an adjective paired by "and" with an adjective that is no verb
    ("lovely and warm", "nice and clean"): said of how something is, never the office's
    service of the same word (to warm, to clean)."""
    return [
        w
        for k, w in enumerate(words)
        if not (
            k >= 2
            and words[k - 1] == "and"
            and _adjective_only(words[k - 2])
            and "ADJ" in language.lemmas(w)
        )
    ]


def _adjective_only(word: str) -> bool:
    said = language.lemmas(word)
    return "ADJ" in said and "VERB" not in said


def answered(out: Screened, live: list[Finding], *, withdrawn: bool) -> Screened:
    """No request left: the replies to what was said, or one "Shall I ...?"."""
    out.outcome = "done"
    offers = [f for f in live if f.offer]
    # "... just curious": the question asked no errand, so nothing is offered
    offering = not any(f.verdict in ("wish", "thanks") or f.meaning == CURIOUS for f in live)
    if len(offers) == 1 and offering:
        out.question = f"{offers[0].message} {offers[0].shall}"
        out.offer = offers[0].offer
        return out
    replies = [f.message for f in live if f.message]
    if any(r.startswith("Noted. ") for r in replies):  # one "Noted", then what to do
        replies = [unnoted(r) for r in replies]
        replies.sort(key=lambda r: not r.startswith("Noted. "))
    if withdrawn:
        replies.insert(0, "OK, I've dropped that request.")
    facts = [f.meaning.removeprefix("a fact: ") for f in live if f.verdict == "fact"]
    if facts:
        replies.append(f"Thanks, noted: {'; '.join(facts)}.")
    if not replies:
        replies = ["Noted."]
    out.decline = " ".join(dict.fromkeys(replies)) + " I did nothing."
    return out


# -- rules ---------------------------------------------------------------------------


def unnoted(reply: str) -> str:
    """ "Noted; I'll keep it in mind." → "I'll keep it in mind." (said once already)."""
    rest = reply.removeprefix("Noted; ")
    return rest[:1].upper() + rest[1:] if rest != reply else reply
