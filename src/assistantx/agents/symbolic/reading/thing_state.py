"""How a thing of the office is, said of the bare thing ("stapler is working fine now",
"calculator is fine again", "label maker is working again"): chat drops the article before
the subject, so a thing's name, a form of "be" and a state (an adjective or a verb's "-ing")
is a statement of how the thing is, never the thing asked for. "thanks, stapler's working
fine now" fetched a colleague's stapler (a wrong physical action); with "the" it was
already read as told. A state that says the speaker wants it ("stapler is urgent",
"scissors are needed") is a need, read as before, and so is a place after "is" ("scissors
are in the kitchen": where they are, read by the rules for it)."""

from __future__ import annotations

from collections.abc import Container

from assistantx.core import language

_BE = frozenset({"is", "are", "was", "were"})
# the complements of "be" that say the thing is wanted, not how it is: the speaker's need
# chat's words for a thing that works, which the word lists read as no adjective
_CHAT_FINE = frozenset({"ok", "k", "oki", "gud"})
_WANTED = frozenset({"urgent", "needed", "required", "wanted", "necessary", "essential", "due"})


def state_told(w: list[str], items: Container[str]) -> bool:
    """Whether ``w`` opens with a thing of ``items`` (a name of one to three words) said
    bare, a form of "be" and the thing's state: an adjective ("fine", "okay") or an ongoing
    verb ("working")."""
    # the longest name of a thing that opens the words ("label maker", "stapler")
    size = next((k for k in (3, 2, 1) if " ".join(w[:k]) in items), 0)
    if not size or len(w) < size + 2 or w[size] not in _BE:
        return False
    state = w[size + 1]
    if state in _WANTED or state in items:
        return False  # "stapler is urgent": asked for; "tea is tea": no state
    # "in", "here" read as adverbs only: where the thing is ("scissors are in the kitchen")
    read = language.lemmas(state)
    return state in _CHAT_FINE or "ADJ" in read or language.is_present_participle(state)
