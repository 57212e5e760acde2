"""A paper the office has no word for, said needed with the work it needs done to it: "need
my cert photocopied", "I need this certificate signed". Said with "get" ("get my cert
photocopied") the work on the requester's own paper is read and restated before anything
moves; said with "need", the unknown noun was read as a thing needed and the message as not
understood ("What should I do?"). The need of a thing with work done to it is the request to
have it done: "(I) need" is said again as "get", read as that.

Only where the words between the determiner and the participle name nothing of the office
(an item the office knows, "need my contract photocopied", is read as before), and the
participle is a form of one of the office's own services or of a colleague's work (sign,
stamp); nothing here knows an office's words: they come from its file.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Collection

from assistantx.core import language

# "(I) need my ... <done>"; never "Wang needs ...", a colleague's need, read as before
_NEED = re.compile(
    r"\b(?:(?:i|we)\s+(?:really\s+|just\s+|still\s+)?)?(?P<need>need|want)\s+"
    r"(?P<det>my|the|this|that|our|these|those)\s+"
    r"(?P<noun>(?:[^\W\d_]+\s+){0,7}?[^\W\d_]+)\s+(?P<done>[^\W\d_]+ed)\b",
    re.IGNORECASE,
)
# the most words a known thing's name and nothing else takes ("my contract", "the tray
# list"); more is the thing with a clause about it ("the book a customer just sold us")
_NAME_ALONE = 2


# "<my unknown thing> need(s) <doing>": the thing said first, the work after it
_NEEDS_DOING = re.compile(
    r"\b(?P<det>my|the|these|those|our)\s+"
    r"(?P<noun>(?:[^\W\d_]+\s+){0,4}?[^\W\d_]+)\s+(?:need|needs)\s+(?P<doing>[^\W\d_]+ing)\b",
    re.IGNORECASE,
)
# "... in my job tray": the office's thing a thing said first is held in
_HELD_IN = re.compile(
    r"\b(?:in|inside|on)\s+(?P<det>my|the|our)\s+(?P<holder>(?:[^\W\d_]+\s+){0,2}[^\W\d_]+)$",
    re.IGNORECASE,
)


def needed_done(
    text: str, work_forms: Collection[str], names_something: Callable[[str], bool]
) -> str:
    """``text`` with each "need my <unknown paper> <work done>" said as "get my ... <done>";
    ``work_forms``: the forms of the office's service and work verbs; ``names_something``:
    whether a phrase names a thing, person or place of the office."""

    def get(m: re.Match[str]) -> str:
        done = m.group("done").lower()
        if done not in work_forms or not language.is_past_participle(done):
            return m.group(0)
        noun = m.group("noun")
        if names_something(noun) and len(noun.split()) <= _NAME_ALONE:
            return m.group(0)  # "need my contract photocopied": a known thing, as before
        if len(noun.split()) > _NAME_ALONE + 1 and not names_something(noun):
            return m.group(0)  # a long phrase of nothing the office knows: read as said
        return f"get {m.group('det')} {m.group('noun')} {m.group('done')}"

    def get_done(m: re.Match[str]) -> str:
        doing = m.group("doing").lower()
        if doing not in work_forms:
            return m.group(0)
        lemma = next(iter(sorted(language.verb_lemmas(doing))), None)
        forms = language.verb_inflections(lemma) if lemma else {}
        done = forms.get("VBN") or forms.get("VBD") or ()  # "tinted"
        if not done:
            return m.group(0)
        det, noun = m.group("det"), m.group("noun")
        held = _HELD_IN.search(noun)
        if held is not None and names_something(held.group("holder")):
            # "the lenses in my job tray": what the work takes is the thing they are in
            det, noun = held.group("det"), held.group("holder")
        elif names_something(noun):
            return m.group(0)  # "my job tray needs tinting": a known thing, as before
        return f"get {det} {noun} {done[0]}"

    return _NEEDS_DOING.sub(get_done, _NEED.sub(get, text))
