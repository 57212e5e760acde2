"""A thing said to need a turn in one of the office's machines, the machine named as the way
its work goes: "my job bag needs a run through the ultrasonic cleaner", "my forceps need a go
in the autoclave", "these parts could do with a run through the washer". English asks for the
machine's work on the thing by naming the machine as its route; read as said, the need of "a
run" (no work of the office) was how the thing is, a statement, and nothing was done.

Where the machine is one of the office's facilities and one of its operations takes the thing
said, the need is said again as the thing put through the machine ("put my job bag through
the ultrasonic cleaner"), which the frames read as that facility's own work on it (its one
operation on the thing, or which of its several is asked), the thing back to its owner.
A machine that takes no such thing ("my mug needs a wash in the microwave" where the
microwave heats lunch), a machine as the subject ("the autoclave needs a run") and a need
with no machine named ("my mug needs a wash") are left as said. The words are English's
(english.yaml ``routed_needs``, ``route_prepositions``); the machines and things the
office's own.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterable

from assistantx.core import english
from assistantx.core.office import Office

_NEEDS = english.entries("routed_needs")
_ROUTES = english.entries("route_prepositions")
# what opens the thing's phrase: an article, a demonstrative, a possessive pronoun
_DETERMINERS = ("my", "our", "the", "this", "that", "these", "those", "his", "her", "their")


def _alternation(phrases: Iterable[str]) -> str:
    ordered = sorted({p for p in phrases if p}, key=lambda p: (-len(p.split()), p))
    return "|".join(r"\s+".join(re.escape(w) for w in p.split()) for p in ordered)


class RoutedWork:
    """Rewrites "<thing> needs a <turn> through the <facility>" as "put <thing> through the
    <facility>" where an operation of that facility takes the thing. ``facilities``: the
    lexicon's names of the office's facilities (phrase → facility id); ``item_types``: the
    item types a phrase names."""

    def __init__(
        self,
        office: Office,
        facilities: dict[str, str],
        item_types: Callable[[str], set[str]],
    ) -> None:
        self._item_types = item_types
        self._facilities = facilities
        self._inputs = {
            f.id: {office.operation(op).input for op in f.operations} - {None}
            for f in office.facilities
        }
        named = [p for p, f in facilities.items() if self._inputs.get(f)]
        self._pattern: re.Pattern[str] | None = None
        if named and _NEEDS and _ROUTES:
            self._pattern = re.compile(
                rf"\b(?P<thing>(?:{'|'.join(_DETERMINERS)}|[^\W\d_]+['’]s)"
                r"(?:\s+[^\W\d_][\w-]*){1,3}?)\s+"
                rf"(?:{_alternation(_NEEDS)})\s+(?:a|an|another)\s+"
                r"(?:[^\W\d_][\w-]*\s+){1,3}?"
                rf"(?:{_alternation(_ROUTES)})\s+"
                r"(?P<det>the|our|that|this|your)\s+"
                rf"(?P<facility>{_alternation(named)})\b",
                re.IGNORECASE,
            )

    def __call__(self, text: str) -> str:
        if self._pattern is None:
            return text

        def put(m: re.Match[str]) -> str:
            facility = self._facilities.get(" ".join(m.group("facility").lower().split()))
            if facility is None or not self._item_types(m.group("thing")) & self._inputs.get(
                facility, set()
            ):
                return m.group(0)
            thing, put = m.group("thing"), "put"
            if thing[:1].isupper() and thing.split()[0].lower() in _DETERMINERS:
                thing, put = thing[:1].lower() + thing[1:], "Put"  # "My job bag ...": opens
            return f"{put} {thing} through {m.group('det')} {m.group('facility')}"

        return self._pattern.sub(put, text)
