"""A service of the office asked on the requester's own thing, for someone outside ("I need
my access card form printed for the visitor", "scan my leave form to PDF for the client"):
the work's product comes back to the requester (a printout brought, a PDF sent to them), who
passes it on; the outsider after "for" is whom it is for, never whom the robot gives it to.
Asked as if the outsider were its recipient, the message was met with "Shall I bring it to
you instead?". Only said with "for": "give it to the visitor" names the outsider as the
recipient and is still asked about.

And a credential's name used as the modifier of another thing of the office ("my *access
card* form", "the *key* request form") names what that thing is about: a document, no
credential handed to anyone."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.screen.pieces import Message
from assistantx.agents.symbolic.reading.screen.terms import Terms

_OWN = frozenset({"my", "our"})
_MODIFIERS = 3  # "my annual leave form": the words between "my" and the thing


def own_thing_serviced(terms: Terms, msg: Message) -> bool:
    """Whether the message says a service verb of the office ("print", "scanned") and the
    requester's own thing ("my leave form")."""
    tokens = msg.lexed.tokens
    if not any(t.word in terms.service_verbs for t in tokens):
        return False
    named = {k for m in msg.lexed.mentions if m.kind == "person" for k in range(m.start, m.end)}
    for m in msg.lexed.mentions:
        if m.kind != "item":
            continue
        for k in range(m.start - 1, max(-1, m.start - 1 - _MODIFIERS), -1):
            if k in named:
                break  # "my colleague Wang's form": someone else's
            if tokens[k].word in _OWN:
                return True  # "my form", "my leave form"
            if tokens[k].opens:
                break
    return False


def modifies_a_thing(msg: Message, mention: Mention) -> bool:
    """Whether ``mention`` (an item) stands right before another item's name in the same
    phrase ("access card" in "access card form"): it says what that thing is about."""
    return any(
        m.kind == "item" and m.start == mention.end and not mention.possessive
        for m in msg.lexed.mentions
    )
