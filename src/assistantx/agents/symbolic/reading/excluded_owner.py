"""Any owner's thing but one colleague's, said from the indefinite owner: "could u bring me a
stapler? anyone's but Wang's", "a pen, anybody's except Lin's". The words name whose thing is
NOT wanted, as "not Wang's" does; left as said, the only owner named was read as the one whose
thing to take (Wang's stapler brought: the one thing the speaker ruled out). The phrase is said
again as the exclusion ("..., not Wang's"), which the screen reads (``screen.exclusion``).

The indefinite doer ruled out ("can anyone but Wang bring me a stapler", "could someone other
than Zhang lend me a pen") names a colleague who is not to do it; the one who lends a thing is
its owner, so that colleague's thing is not wanted either (Wang's stapler had been brought:
the doer's name was the only owner said). The colleague is taken out of the subject and the
exclusion said at the end of the sentence (", not Wang's"), read as above; a maker or a signer
ruled out is not asked by name either, as nothing else names them."""

from __future__ import annotations

import re
from collections.abc import Callable

from assistantx.core import english

_ANY_BUT = re.compile(
    r"(?P<pause>[,.;:?!]\s*|\s+-+\s*|\s+|^)"
    rf"\b(?:{english.alternation('any_owners_but')})\s+(?:{english.alternation('owner_left_out_by')})"
    r"\s+(?=\w)",
    re.IGNORECASE,
)


# "anyone but Wang", "someone other than Zhang": the indefinite doer and the colleague left out
_ANYONE_BUT = re.compile(
    r"\b(?P<who>anyone|anybody|someone|somebody|one of you)\s+"
    rf"(?:{english.alternation('owner_left_out_by')})\s+"
    r"(?P<name>[^\W\d_][\w'’-]*(?:\s+[A-Z][\w'’-]*)?)"
    r"(?P<rest>[^.?!;]*)",
    re.IGNORECASE,
)


def excluded_owners(text: str, is_person: Callable[[str], bool] | None = None) -> str:
    """``text`` with each "anyone's but X's" said as the exclusion ", not X's", and, where
    ``is_person`` says X is a colleague's name and nothing else, each "anyone but X
    <request>" as "anyone <request>, not X's"."""
    text = _ANY_BUT.sub(_as_exclusion, text)
    if is_person is None:
        return text
    return _ANYONE_BUT.sub(lambda m: _doer_left_out(m, is_person), text)


def _doer_left_out(m: re.Match[str], is_person: Callable[[str], bool]) -> str:
    words, rest = m.group("name").split(), m.group("rest")
    # "except Wang Fang bring ...": the full name where both words name the colleague, else
    # the first word alone, the second given back to the request ("except Wang bring ...")
    if len(words) == 2 and not is_person(" ".join(words)):
        words, rest = words[:1], f" {m.group('name').split(maxsplit=1)[1]}{rest}"
    name = " ".join(words)
    if not is_person(name) or not rest.strip():
        return m.group(0)  # "anyone but me", "anything but that": no colleague left out
    said = rest.rstrip()
    return f"{m.group('who')}{said}, not {name}'s{rest[len(said) :]}"


def _as_exclusion(m: re.Match[str]) -> str:
    pause = m.group("pause")
    if not pause.strip():  # "bring a pen anyone's but Lin's": the exclusion is a clause of its own
        return ", not " if m.start() > 0 else "not "
    return f"{pause.rstrip()} not "
