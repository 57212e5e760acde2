"""A colleague's given name said clipped, with a possessive: "Rhi's plan" for Rhiannon,
"Alex's" for Alexandra, where the office declares no such alias. The clip is at least three
letters and a true prefix of the given name (the first word of the person's name); one that
clips two people's names means either, so whom is asked; one the office uses for anything
else is never a clip. Only a possessive is read so ("Rhi's ruler"): a bare short word is too
often something else. A clip that is an English word ("Pat's" for Patricia) counts only
written with its capital.
"""

from __future__ import annotations

from collections.abc import Collection, Iterable

from assistantx.core import language

_SHORTEST = 3


def given_name_clips(
    people: Iterable[tuple[str, str]], taken: Collection[str]
) -> dict[str, tuple[str, ...]]:
    """Clip → the ids of everyone whose given name it clips, for ``(full name, id)`` pairs;
    ``taken``: the words the office already uses (names, items, places)."""
    found: dict[str, set[str]] = {}
    for name, ident in people:
        words = name.split()
        if not words:
            continue
        given = language.fold(words[0])
        if not given.isalpha():
            continue
        for end in range(_SHORTEST, len(given)):
            clip = given[:end]
            if clip not in taken:
                found.setdefault(clip, set()).add(ident)
    return {clip: tuple(sorted(ids)) for clip, ids in found.items()}


def clipped_owner(
    word: str, written: str, possessive: bool, clips: dict[str, tuple[str, ...]]
) -> tuple[str, ...]:
    """The people a possessive clipped given name may mean (none when it is no such clip)."""
    if not possessive or word not in clips:
        return ()
    if language.is_english_word(word) and not written[:1].isupper():
        return ()
    return clips[word]
