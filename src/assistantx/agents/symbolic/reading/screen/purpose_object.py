"""How many words after a purpose's verb belong to the purpose the office declares: "something
to check *continuity* with" where a multimeter's purposes include "check continuity", "to
take *notes* with", "to write *on*". A purpose names its tool by the verb and its object
together, so the object is part of the phrase: never left behind to be glued to the tool's
name ("a multimeter continuity"). The longest declared phrase wins ("check continuity" over
"check"); none: no word (the verb alone is the purpose)."""

from __future__ import annotations

from collections.abc import Callable, Sequence

# "check the continuity of the loom" is said, never declared: a purpose is short
_LONGEST_OBJECT = 3


def purpose_words(declared: Callable[[str], list[str]], verb: str, tail: Sequence[str]) -> int:
    """The number of words of ``tail`` (the words after the purpose's verb) that, with
    ``verb``, make the longest purpose ``declared`` knows an item for; 0 when none does."""
    for n in range(min(_LONGEST_OBJECT, len(tail)), 0, -1):
        if declared(" ".join([verb, *(w.lower() for w in tail[:n])])):
            return n
    return 0
