"""A person named by a title and a name nobody of the office has: "Mrs Jenkins", "Dr Alvarez",
"Mr Okoro" (blind round 139's class).

English names a stranger by title and surname ("Mr/Mrs/Ms/Miss/Mx/Dr/Prof" before a
capitalised word); where that word names nobody, no group and nothing of the office, the
person is outside it, never a colleague to ask about. Two readings follow from it, with no
list of outsiders' names:

- where the person would receive a hand-over ("give Mr Evans my stapler", "bring my stapler
  to Mrs Jenkins") they are an outsider recipient like "the client": the screen's outsider
  rule asks (only colleagues are handed anything);
- where they are only whom the work is for ("one for Mrs Jenkins", "book a slot for Mr Evans
  and bring me the card") the purpose is context, and the reader does not ask who they are:
  the screen has already taken every "for" that hands a thing to them.
"""

from __future__ import annotations

from collections.abc import Collection, Sequence

from assistantx.agents.symbolic.reading.tokens import Token

# the forms of address before a surname (with or without the stop: the tokens drop it)
TITLES = frozenset({"dr", "mr", "mrs", "ms", "mx", "miss", "prof", "professor", "doctor"})


def titled_stranger(tokens: Sequence[Token], at: int, office_at: Collection[int]) -> bool:
    """Whether token ``at`` is a capitalised name after a title, and neither it nor its title
    is a word of the office's own names (``office_at``: the tokens the lexicon read as the
    office's people, groups, items, places or facilities)."""
    if at < 1 or at in office_at or (at - 1) in office_at:
        return False
    title, name = tokens[at - 1], tokens[at]
    if title.word not in TITLES or name.after_pause or name.possessive:
        # "Mr Evans's notes": whose, the possessive's own reading (``outsider_owner``)
        return False
    # "PDF" after "Dr" is no surname; "O'Brien" is
    return name.text[:1].isupper() and not name.text.isupper()
