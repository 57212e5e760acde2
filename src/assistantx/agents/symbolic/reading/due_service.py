"""A thing said to be due one of the office's services: "my 4-gas is due a bump test", "the
van's overdue for a service", "my seed samples are due a dry". English says the thing needs
that service, as "my 4-gas needs a bump test" does, and the owner saying it asks for it; read
as a plain statement, the request was lost, and a "take it down to ..." after it moved the
thing with no service named. The services are the office's own (its operations' declared
verbs, display names and the nouns the lexicon reads as them), never a list here; "due" of
anything else ("my report is due on Friday", "due a visit") is left as said.

The same request said as the thing's going or being sent for the service: "can my harness go
(in) for inspection", "could my van go in for a service", "send my harness (off) for an
inspection" ask for the service on the thing, as "my harness needs an inspection" does; read as
said, the thing was fetched or handed to someone and straight back, with no service done. Only
a service of the office's own after "for" ("send my mug for a wash" where nothing washes stays
as said), and never a colleague or a place after "to" ("send it to Wang for mending":
``sent_for_service``)."""

from __future__ import annotations

import re
from collections.abc import Iterable

from assistantx.core.office import Office
from assistantx.memory.names import normalize

# What may stand between "due (for)" and the service: an article or a possessive (a
# colleague's too: "due Zhang's signature"), and up to two describing words ("due a *quick*
# bump test", "due its *annual* service").
_OPENERS = r"(?:a|an|another|the|its|their|his|her|my|our|your|[^\W\d_][\w.-]*['’]s)"


def _alternation(phrases: Iterable[str]) -> str:
    ordered = sorted({p for p in phrases if p}, key=lambda p: (-len(p.split()), p))
    return "|".join(r"[\s-]+".join(re.escape(w) for w in p.split()) for p in ordered)


# The thing said going for the service: "my harness", "the van", "this buckle's strap".
# (a word of its name is no preposition: "send my harness *to Tom* for inspection" is not one)
# A pronoun too, for the thing said before it ("the strings on my racket are shot, can it go
# for a restring": ``referent`` reads "it" after this).
_THING = (
    r"(?P<thing>(?:it|them)(?=\s)|(?:my|our|the|this|that|these|those|his|her|their)"
    r"(?:\s+(?!(?:to|for|in|off|away|out|over|with|from|at|by)\b)[^\W\d_][\w-]*){1,3}?)"
)


class DueService:
    """Rewrites "<thing> is (over)due (for) a <service>" as "<thing> needs a <service>".
    ``nouns``: the words the lexicon reads as a service besides its declared verbs and
    names: the nouns of operations ("a lamination") and of a colleague's work on a paper
    ("a signature", "a stamp")."""

    def __init__(self, office: Office, nouns: Iterable[str] = ()) -> None:
        phrases = {
            normalize(said)
            for op in office.operations
            for said in (*op.verbs, op.name)
            if op.verbs or op.name
        }
        phrases |= {normalize(n) for n in nouns}
        self._pattern: re.Pattern[str] | None = None
        self._goes: re.Pattern[str] | None = None
        if phrases:
            service = (
                rf"(?=(?:(?:{_OPENERS})\s+)?(?:[a-z0-9-]+\s+){{0,2}}?"
                rf"(?:{_alternation(phrases)})\b)"
            )
            # "can my harness go in for (an) inspection", "send my harness off for inspection",
            # "book my racket in for a restring"
            self._goes = re.compile(
                rf"\b(?:(?:can|could|will|would|may|should)\s+{_THING}\s+"
                rf"(?:go|be\s+(?:sent|booked))"
                rf"|(?:(?:can|could|will|would)\s+you\s+(?:please\s+)?)?(?:send|book)\s+"
                rf"{_THING.replace('thing', 'sent')})"
                rf"\s+(?:(?:in|off|away|out)\s+)?for\s+{service}",
                re.IGNORECASE,
            )
            self._pattern = re.compile(
                r"(?P<be>\s+(?:is|are)\s+|['’](?:s|re)\s+)(?:now\s+|well\s+|long\s+)?"
                r"(?:over)?due\s+(?:for\s+)?"
                rf"(?=(?:{_OPENERS})\s+(?:[a-z0-9-]+\s+){{0,2}}?(?:{_alternation(phrases)})\b)",
                re.IGNORECASE,
            )

    def __call__(self, text: str) -> str:
        if self._goes is not None:
            text = self._goes.sub(lambda m: f"{m.group('thing') or m.group('sent')} needs ", text)
        if self._pattern is None:
            return text

        def needs(match: re.Match[str]) -> str:
            be = match.group("be").strip().lower().lstrip("'’")
            return " need " if be in ("are", "re") else " needs "

        return self._pattern.sub(needs, text)
