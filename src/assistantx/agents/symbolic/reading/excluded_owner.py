"""Any owner's thing but one colleague's, said from the indefinite owner: "could u bring me a
stapler? anyone's but Wang's", "a pen, anybody's except Lin's". The words name whose thing is
NOT wanted, as "not Wang's" does; left as said, the only owner named was read as the one whose
thing to take (Wang's stapler brought: the one thing the speaker ruled out). The phrase is said
again as the exclusion ("..., not Wang's"), which the screen reads (``screen.exclusion``).

Only the indefinite owner's possessive ("anyone's", "anybody's") opens it: "can anyone but Wang
bring me a pen" rules out a doer, not an owner, and is left as said."""

from __future__ import annotations

import re

from assistantx.core import english

_ANY_BUT = re.compile(
    r"(?P<pause>[,.;:?!]\s*|\s+-+\s*|\s+|^)"
    rf"\b(?:{english.alternation('any_owners_but')})\s+(?:{english.alternation('owner_left_out_by')})"
    r"\s+(?=\w)",
    re.IGNORECASE,
)


def excluded_owners(text: str) -> str:
    """``text`` with each "anyone's but X's" said as the exclusion ", not X's"."""
    return _ANY_BUT.sub(_as_exclusion, text)


def _as_exclusion(m: re.Match[str]) -> str:
    pause = m.group("pause")
    if not pause.strip():  # "bring a pen anyone's but Lin's": the exclusion is a clause of its own
        return ", not " if m.start() > 0 else "not "
    return f"{pause.rstrip()} not "
