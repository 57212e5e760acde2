"""Pronoun exclusion: "could I borrow Farida's wide lens tonight? not her camera": "not
his/her/their X" after exactly one colleague was named is that colleague's X, not wanted; a
hint like "not Chen's", never a party nor a question of whom "her" means. After two colleagues
it asks whom the pronoun means (a name said after it answers), and is never read as a request
of its own."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core.task_schema import Hint

_THIRD_POSSESSIVES = frozenset({"his", "her", "their"})
_FILLERS = frozenset({"but", "though", "just", "please", "and", "definitely", "so"})


def pronoun_exclusion(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    words = [w for w in piece.words if w not in _FILLERS]
    if len(words) < 3 or words[0] not in terms.en.exclusion_openers:
        return None
    if words[1] not in _THIRD_POSSESSIVES:
        return None
    items = terms.named(piece.lexed, "item")
    if len(items) != 1 or terms.named(piece.lexed, "person"):
        return None
    before = {
        p
        for earlier in msg.pieces
        if earlier.end <= piece.start
        for p in terms.named(earlier.lexed, "person")
        if p != requester
    }
    after = {
        p
        for later in msg.pieces
        if later.start >= piece.end
        for p in terms.named(later.lexed, "person")
        if p in before
    }
    if len(before) > 1 and len(after) == 1:
        before = after  # "... not her camera. Farida": the answer to whom "her" means
    if not before:
        return None  # nobody named: whom "her" means is asked by the frames
    if len(before) > 1:
        # two people named before: whom "her" means is asked, and the piece is never read
        # as a request of its own ("not Kwame's camera" is no errand)
        said = next(w for w in piece.lexed.tokens if w.word in _THIRD_POSSESSIVES).text
        question = f"Who do you mean by {said!r}? Please tell me their name."
        return Finding("which", piece, f"whom {said!r} means is asked", message=question)
    (person,) = before
    who = terms.office.person(person).name
    thing = terms.office.item_type(items[0]).name
    hint = Hint(
        kind="condition", person=person, value="not wanted", item_type=items[0], said=piece.text
    )
    return Finding("exclusion", piece, f"not {who}'s {thing}", hint)
