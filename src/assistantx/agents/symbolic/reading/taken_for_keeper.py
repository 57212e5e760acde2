"""A thing taken "for" the colleague who keeps the service it needs: "my bow needs rehairing,
can you take it down to the store for Frank?", "my guitar needs restringing, could you drop it
at the workshop for Nell?".

Where the message names a service of the office (a need's "-ing", "needs a rehair", the verb
itself) and the colleague after "for" keeps a facility that offers it, "take it (to the
place) for <keeper>" asks that keeper to do the work: the clause is said as "could <keeper>
<verb> it", which the reader already reads as the service done by them and the thing back
with its owner. Read as said, the thing was handed to the keeper and left there. A carrying
with no service the keeper runs named ("can you take my stapler to Wang", "take it over for
Wang" where Wang keeps nothing that does it) is left as said: a delivery."""

from __future__ import annotations

import re
from collections.abc import Callable

from assistantx.core import language
from assistantx.core.office import Office

_WORD = r"[^\W\d_][\w'’-]*"
_THING = rf"(?P<thing>it|them|(?:my|our)(?:\s+{_WORD}){{1,3}}?)"
_CARRIED = re.compile(
    rf"\b(?:(?:can|could|would|will)\s+(?:you|u|ya)\s+)?(?:(?:please|pls|just)\s+)?"
    rf"(?:take|bring|carry|run|drop|send|pop|walk)\s+{_THING}\s+"
    r"(?:(?:down|over|up|round|across|along)\s+)?"
    rf"(?:(?:to|at|into|in)\s+(?:the\s+|his\s+|her\s+|their\s+)?{_WORD}(?:\s+{_WORD})?\s+)?"
    rf"for\s+(?P<who>{_WORD}(?:\s+{_WORD})??)"
    r"(?=\s*(?:please|pls|thanks|thx)?\s*(?:[?.!,;]|$))",
    re.IGNORECASE,
)
_WORDS = re.compile(r"[^\W\d_]+")


def kept_services(office: Office) -> dict[str, frozenset[str]]:
    """Each keeper's services, by the verbs that name them (the operation's verbs and the
    first word of its name), over every facility they keep."""
    out: dict[str, set[str]] = {}
    for facility in office.facilities:
        verbs: set[str] = set()
        for op_id in facility.operations:
            op = office.operation(op_id)
            verbs.update(v.lower() for v in op.verbs)
            verbs.update(op.name.lower().split()[:1])
        for keeper in facility.guards:
            out.setdefault(keeper, set()).update(verbs)
    return {k: frozenset(v) for k, v in out.items()}


def _named_service(text: str, services: frozenset[str]) -> str | None:
    """The verb of one of ``services`` the text names ("rehairing", "a rehair")."""
    said = set(_WORDS.findall(text.lower()))
    # "rehairing", "a rehair", "restrung": any form of the verb (the noun is its bare form)
    return next((v for v in sorted(services) if said & {v, *language.verb_forms(v)}), None)


def taken_for_keeper(
    text: str,
    keepers: dict[str, frozenset[str]],
    people_of: Callable[[str], tuple[str, ...]],
    name_of: Callable[[str], str],
) -> str:
    """``text`` with "take it ... for <keeper>" said as "could <keeper> <verb> it" where the
    text names a service that keeper runs (``keepers``: ``kept_services``). ``people_of``:
    every colleague the words may name ("Frank": Frank Osei, and Liesl Frank by her surname);
    of several, the one who keeps the service named is meant, said by their full name
    (``name_of``) so no later step asks which."""

    def said(m: re.Match[str]) -> str:
        ids = people_of(m.group("who"))
        rest = text[: m.start()] + text[m.end() :]
        fit = [i for i in ids if i in keepers and _named_service(rest, keepers[i]) is not None]
        if len(fit) != 1:
            return m.group(0)  # "take my stapler over for Wang": a delivery
        who = fit[0]
        verb = _named_service(rest, keepers[who])
        name = m.group("who") if len(ids) == 1 else name_of(who)
        return f"could {name} {verb} {m.group('thing')}"

    return _CARRIED.sub(said, text)
