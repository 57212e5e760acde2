"""A verb of hurrying with a particle of going across, before "to": "can you *run* mine *over
to* her", "*pop* my stapler *across to* Wang", "*nip* the form *round to* Sue". The idiom
carries its object to whom "to" names: it is a giving verb, said again as "take <object> to"
(fix180a class 4: after "Wang needs a stapler", "run mine over to her" was read beside the
need as a second errand, and a colleague's stapler was taken for the need besides mine).

Only with one to five words of object between the verb and the particle, none of them "to"
or a clause's end; "to them" (a desk or team named before, ``reading.errand``) is left to the
errand's own rules."""

from __future__ import annotations

import re

from assistantx.core import english

# the verbs of hurrying that lead a carrying idiom ("run", "pop", "nip"), not "go"/"come"/"help"
_HURRYING = english.words("serial_verbs") - {"go", "come", "help", "try"}
_ACROSS = english.words("errand_particles")

_IDIOM = re.compile(
    rf"\b(?:{'|'.join(sorted(_HURRYING))})\s+"
    r"(?P<object>(?:(?!to\b)[\w'’-]+\s+){0,4}(?!to\b)[\w'’-]+)\s+"
    rf"(?:{'|'.join(sorted(_ACROSS))})\s+to\s+(?!them\b)",
    re.IGNORECASE,
)


def hurried_errands(text: str) -> str:
    """``text`` with each hurrying verb's carrying idiom said as "take <object> to"."""
    return _IDIOM.sub(lambda m: f"take {m.group('object')} to ", text)
