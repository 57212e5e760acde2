"""Each part of a combined request owns the recipient said inside its own stretch of text.

"print my file and take it to Wang, oh and a coffee for me": "take it to Wang" belongs to the
print (the printout goes to Wang), "for me" to the coffee. Two ways a recipient crossed into a
neighbouring part, and handed each thing to the other's person (a wrong physical action):

- ``after_a_new_object``: "for me" ending a clause after "to Wang" was read as a favour ("take
  my stapler to Zhang for me") even when a new object stood between them ("bring my stapler to
  Wang and a coffee for me"); there it says whom that new object is for.
- ``closes_a_part``: a clause that hands on the thing said before ("take it to Wang", "bring
  them over to Zhang") is a whole part once its recipient is named; an object after a join
  ("and", "plus", "also", a comma) starts a part of its own, so the earlier thing keeps its
  recipient and the new object gets its own. Where the recipient comes after both objects
  ("bring them and a coffee to Zhang") the clause is not closed before the join, and both
  go to the one recipient: ``handed_along`` gives the thing said before that recipient too.

A recipient said of all the parts ("print my file and a coffee, *both* for Wang", "..., all
to Zhang") is every part's that named none of its own: ``shared_recipient``.

A new part that names no recipient of its own ("take it to Wang, and a coffee") may be for
the requester or for Wang: ``names_a_recipient`` is false, and the whole request is restated
and asked before anything moves.
"""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.left_with import left_with
from assistantx.agents.symbolic.reading.mention_view import MentionView
from assistantx.agents.symbolic.reading.tokens import Token, prev_word
from assistantx.core import english
from assistantx.core.receiving_place import MEET_AT, PLACE_WORDS

# "it", "them", "this", "those": the thing said before, handed on by the clause
_BACK_REFERENCES = frozenset({"it", "them", "this", "that", "these", "those"})
# the words before a person that name them as whom the thing goes to
_RECEIVING = frozenset({"to", "for"})
# words that may stand between a join and the object it adds ("oh and also a coffee")
_FILLERS = english.words("skip_after_join") | frozenset({"oh", "ah", "and", "plus", "also"})
# words that open a noun phrase before its item ("some water", "another coffee")
_DETERMINERS = english.words("object_starts") | frozenset({"some", "another", "any", "more"})
_OWN_WORDS = frozenset({"my", "our"})
_DATIVE_VERBS = english.words("dative_verbs")
# the words that add a second object to the one before: "them and a coffee"
_ALONG = frozenset({"and", "plus"})
# "both for Wang", "all to Zhang", "each for me": the phrase is said of every thing before
_ALL_OF_THEM = frozenset({"both", "all", "each"})


def after_a_new_object(ms: Sequence[MentionView], recipient_at: int, at: int) -> bool:
    """Whether an item is named between a recipient at token ``recipient_at`` and the
    receiving phrase at token ``at``: the later phrase is that item's, not the earlier's."""
    return any(m.kind == "item" and recipient_at < m.start < at for m in ms)


def _hands_back_reference_on(current: Sequence[MentionView], tokens: Sequence[Token]) -> bool:
    """Whether a clause hands on "it"/"them" (naming no thing of its own) to someone named
    after it: "take it to Wang", "bring them over to me"."""
    if any(m.kind == "item" for m in current) or not any(m.kind == "cue" for m in current):
        return False
    back = [
        m.start
        for m in current
        if m.kind == "pronoun" and not m.possessive and tokens[m.start].word in _BACK_REFERENCES
    ]
    return bool(back) and any(m.start > back[0] and _receives(m, tokens) for m in current)


def _receives(m: MentionView, tokens: Sequence[Token]) -> bool:
    """Whether a person mention says whom the thing goes to: after "to"/"for", after the
    "with" of a verb that puts a thing down ("drop it with Zhang"), or as the owner of the
    place it is left at ("leave it on Zhang's desk")."""
    if m.kind not in ("person", "self", "pronoun"):
        return False
    before = prev_word(tokens, m.start)
    if m.possessive:
        after = tokens[m.end].word if m.end < len(tokens) else ""
        return before in MEET_AT and after in PLACE_WORDS
    return before in _RECEIVING or left_with([t.word for t in tokens], m.start)


def _opens_object(ms: Sequence[MentionView], n: int, tokens: Sequence[Token]) -> bool:
    """Whether mention ``n`` (past words that only join) opens a new object: an item, or an
    owner's word right before one ("my stapler", "Wang's mug")."""
    while n < len(ms) and tokens[ms[n].start].word in _FILLERS and ms[n].kind == "word":
        n += 1
    while n < len(ms) and tokens[ms[n].start].word in _DETERMINERS and ms[n].kind == "word":
        n += 1
    if n >= len(ms):
        return False
    first = ms[n]
    if first.kind == "item":
        return True
    owner = first.possessive or (first.kind == "self" and tokens[first.start].word in _OWN_WORDS)
    return owner and n + 1 < len(ms) and ms[n + 1].kind == "item"


def closes_a_part(
    current: Sequence[MentionView], ms: Sequence[MentionView], n: int, tokens: Sequence[Token]
) -> bool:
    """Whether the clause so far (``current``) is a whole part, handing the thing said before
    to its recipient, and mention ``n``, after a join, opens an object of a new part."""
    return _hands_back_reference_on(current, tokens) and _opens_object(ms, n, tokens)


def names_a_recipient(ms: Sequence[MentionView], tokens: Sequence[Token]) -> bool:
    """Whether a part names whom its thing goes to: a person, "me" or "him" after "to"/"for",
    or after a verb of giving ("get me a coffee")."""
    return any(
        m.kind in ("person", "self", "pronoun")
        and not m.possessive
        and prev_word(tokens, m.start) in _RECEIVING | _DATIVE_VERBS
        for m in ms
    )


def handed_along(
    ms: Sequence[MentionView], tokens: Sequence[Token], recipient_at: Sequence[int]
) -> bool:
    """Whether a clause hands on the thing said before together with a new object: "bring
    *them and* a coffee to Zhang" (the back reference right before "and", no recipient
    itself, as "bring them a coffee" would be)."""
    return any(
        m.kind == "pronoun"
        and not m.possessive
        and tokens[m.start].word in _BACK_REFERENCES
        and m.start not in recipient_at
        and m.end < len(tokens)
        and tokens[m.end].word in _ALONG
        and _opens_object(ms, n + 1, tokens)
        for n, m in enumerate(ms)
    )


def coordinated(tokens: Sequence[Token], m: MentionView) -> bool:
    """Whether "and"/"plus" follows a pronoun right after a giving verb: "bring *them and* a
    coffee" hands them on with the coffee; "bring them a coffee" gives them the coffee."""
    return m.end < len(tokens) and tokens[m.end].word in _ALONG


def shared_recipient(
    tokens: Sequence[Token], recipient: Sequence[str], recipient_at: Sequence[int]
) -> str | None:
    """Whom a clause's receiving phrase said of all the parts names ("both for Wang"), else
    None."""
    for who, at in zip(recipient, recipient_at, strict=True):
        k = at - 1
        if k >= 1 and tokens[k].word in _RECEIVING and tokens[k - 1].word in _ALL_OF_THEM:
            return who
    return None
