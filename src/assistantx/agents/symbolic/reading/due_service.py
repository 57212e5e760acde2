"""A thing said to be due one of the office's services: "my 4-gas is due a bump test", "the
van's overdue for a service", "my seed samples are due a dry". English says the thing needs
that service, as "my 4-gas needs a bump test" does, and the owner saying it asks for it; read
as a plain statement, the request was lost, and a "take it down to ..." after it moved the
thing with no service named. The services are the office's own (its operations' declared
verbs, display names and the nouns the lexicon reads as them), never a list here; "due" of
anything else ("my report is due on Friday", "due a visit") is left as said."""

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
        if phrases:
            self._pattern = re.compile(
                r"(?P<be>\s+(?:is|are)\s+|['’](?:s|re)\s+)(?:now\s+|well\s+|long\s+)?"
                r"(?:over)?due\s+(?:for\s+)?"
                rf"(?=(?:{_OPENERS})\s+(?:[a-z0-9-]+\s+){{0,2}}?(?:{_alternation(phrases)})\b)",
                re.IGNORECASE,
            )

    def __call__(self, text: str) -> str:
        if self._pattern is None:
            return text

        def needs(match: re.Match[str]) -> str:
            be = match.group("be").strip().lower().lstrip("'’")
            return " need " if be in ("are", "re") else " needs "

        return self._pattern.sub(needs, text)
