"""The requester's reply to an offer made beside an answer ("As far as I know, Teodor has a
tape measure. Shall I bring you one?"): the question was answered already, so only a plain
yes for now carries the offer out. A yes for a later time ("tomorrow is fine") puts it off, a
reply that says neither ("hmm, not sure", "I'll ask him") leaves the answer as it was, and a
reply that is itself a request ("bring it to my bench") is read with the message as before."""

from __future__ import annotations

from typing import Literal

from assistantx.agents.symbolic.answers import Stance, offer_stance, says_not_known
from assistantx.agents.symbolic.reading.speech import SpeechActs
from assistantx.core import language

OfferReply = Literal["yes", "no", "later", "unclear", "request"]
# Sounds that open a reply and say nothing: "hmm, not sure" is as unsure as "not sure".
_FILLERS = frozenset({"hmm", "hm", "um", "uh", "er", "erm", "well", "oh", "ah"})

LATER = "OK, tell me when you need it and I'll bring it then. I did nothing."
LEFT = "OK, I'll leave it there; tell me if you do want me to bring one. I did nothing."


def not_known(answer: str) -> bool:
    """A reply that only says they do not know ("hmm, sorry, I don't know more than I
    wrote"): no answer to the question at all."""
    return says_not_known(" ".join(w for w in language.words(answer) if w not in _FILLERS))


def plain_stance(answer: str) -> Stance:
    """Whether a reply to any "Shall I ...?" accepts it; "hmm, not sure" is no yes,
    whatever its "sure" says."""
    return "unclear" if not_known(answer) else offer_stance(answer)


def offer_reply(speech: SpeechActs, answer: str) -> OfferReply:
    """What a reply to an answered question's "Shall I ...?" does."""
    words = language.words(answer)
    stance = plain_stance(answer)
    if stance == "yes":
        return "later" if speech.later(words) else "yes"
    if stance == "no":
        return "no"
    return "request" if speech.request(words) else "unclear"
