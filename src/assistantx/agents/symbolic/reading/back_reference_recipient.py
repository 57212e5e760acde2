"""A colleague's thing asked for the speaker, then referred back to as another person's need:
for whom, asked.

"could I have Wang's budget plan? Zhang needs the file": the first clause asks for Wang's
thing for the speaker; the later clause refers back to it ("the file", "it", "that": the
thing just described, Wang's, never the speaker's own) and says Zhang needs it. The two say
different recipients and nothing decides between them, so the reader asks ("Wang's budget
plan file for you, or for Zhang Wei?") before anything moves; the answer says which.

The rule reads English and the office's own names only:

- the thing: a colleague's possessive ("Wang's"), plain describing words, then an item of
  the office ("Wang's budget plan file", said so by ``described_items.named_later`` where
  the later clause named the item), in a clause that names the speaker ("I", "me");
- the later clause (after a sentence or clause break): a back-reference to it ("the <same
  item>" or "it"/"that"/"this", nobody's) and another colleague as its recipient: the one
  who needs or wants it ("Zhang needs it"), or after "to"/"for" ("pass the file to Zhang");
  not negated ("Zhang doesn't need the file" asks for nothing), and not the speaker again.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from assistantx.agents.symbolic.reading.lexicon import Lexicon, Mention
from assistantx.agents.symbolic.reading.tokens import Token, clause_end, clause_start
from assistantx.core import english, language

# The words that make a person the one a thing is for: "Zhang needs it", "to Zhang".
_NEEDS = english.words("need_verbs")
_FOR_WHOM = frozenset({"to", "for"})
_BACK = frozenset({"the", "that", "this"})  # "the file", "that file"
_BACK_PRONOUNS = frozenset({"it", "that", "this"})
_NEGATORS = english.words("statement_negations") | {"neednt"}  # "Zhang doesn't need it"
# "Zhang would like the file", "Zhang could use it": a want said with a helping verb
_MODAL_WANTS = tuple(tuple(p.split()) for p in english.entries("modal_wants"))
_SELF = english.words("self_words") - {"my", "mine"}  # the speaker as a party: "I", "me"
_DESCRIBING = frozenset({"word"})
_LONGEST = 4  # describing words before the item ("quarter end budget plan")
_OR_FOR = " for you, or for "  # the question's words between the thing and the other
_YOU = frozenset({"you", "u", "me", "myself", "mine", "i"})


@dataclass(frozen=True)
class Doubt:
    """The thing as said, whose it is, and the other colleague the later clause names."""

    thing: str  # "Wang's budget plan file"
    owner: str
    other: str  # the later clause's recipient (a person id)
    question: str


def recipient_as_need(tokens: Sequence[Token], m: Mention) -> bool:
    """Whether person mention ``m`` is said as the one a thing is for: the subject of a need
    ("Zhang needs", "Zhang wants") or after "to"/"for" ("pass it to Zhang")."""
    if m.kind != "person" or m.possessive or len(m.ids) != 1:
        return False
    after = tuple(t.word for t in tokens[m.end : m.end + 2])
    before = tokens[m.start - 1].word if m.start > 0 else ""
    wants = after[:1] in {(w,) for w in _NEEDS} or any(after[: len(p)] == p for p in _MODAL_WANTS)
    return wants or before in _FOR_WHOM


def recipient_in_doubt(lex: Lexicon, text: str, requester: str) -> Doubt | None:
    """The doubt of ``text`` (see the module); None where there is none."""
    lexed = lex.read(text)
    tokens, mentions = lexed.tokens, lexed.mentions
    for n, opener in enumerate(mentions):
        if opener.kind != "person" or not opener.possessive or len(opener.ids) != 1:
            continue
        owner = opener.ids[0]
        if owner == requester:
            continue
        item = _item_after(tokens, mentions, n + 1, opener.end)
        if item is None:
            continue
        start = clause_start(tokens, opener.start)
        stop = clause_end(tokens, item.end)
        if stop >= len(tokens) or not _names_speaker(mentions, start, stop):
            continue
        other = _later_recipient(tokens, mentions, stop, item, {owner, requester})
        if other is None:
            continue
        spans = [m.span() for m in language.WORD.finditer(text.replace("’", "'"))]
        if len(spans) != len(tokens):
            return None
        thing = text[spans[opener.start][0] : spans[item.end - 1][1]]
        name = lex.office.person(other).name
        return Doubt(thing, owner, other, f"{thing}{_OR_FOR}{name}?")
    return None


def chosen_recipient(lex: Lexicon, question: str, answer: str) -> str | None:
    """The request as the answer to the doubt's question chose it: "get Wang's budget plan
    file for Zhang Wei" or "... for me"; None where the question is not this one or the
    answer names neither or both."""
    thing, mark, rest = question.partition(_OR_FOR)
    if not mark or not rest.endswith("?"):
        return None
    named = [m for m in lex.read(rest[:-1]).mentions if m.kind == "person"]
    if len(named) != 1 or len(named[0].ids) != 1:
        return None
    said = lex.read(answer)
    people = {i for m in said.mentions if m.kind == "person" and not m.possessive for i in m.ids}
    other = named[0].id in people
    mine = bool(_YOU & {t.word for t in said.tokens})
    if other == mine:
        return None
    whom = lex.office.person(named[0].id).name if other else "me"
    return f"get {thing} for {whom}"


def _item_after(
    tokens: Sequence[Token], mentions: Sequence[Mention], k: int, at: int
) -> Mention | None:
    """The office item said right after a possessive, after plain describing words at most
    ("Wang's budget plan file"); None where something else comes first."""
    first = at
    for m in mentions[k:]:
        if m.start != at or tokens[m.start].opens or tokens[m.start].after_pause:
            return None
        if m.kind == "item":
            return m if len(m.ids) == 1 and not m.possessive else None
        if m.kind not in _DESCRIBING or m.end - first > _LONGEST:
            return None
        at = m.end
    return None


def _names_speaker(mentions: Sequence[Mention], start: int, stop: int) -> bool:
    """Whether the speaker is a party of the clause ("could I have", "send me")."""
    return any(m.kind == "self" and not m.possessive and start <= m.start < stop for m in mentions)


def _later_recipient(
    tokens: Sequence[Token],
    mentions: Sequence[Mention],
    start: int,
    item: Mention,
    not_them: set[str],
) -> str | None:
    """The colleague the clause from ``start`` says needs the thing, where it refers back to
    it and is not negated; None otherwise."""
    stop = clause_end(tokens, start + 1)
    words = {t.word for t in tokens[start:stop]}
    if words & _NEGATORS:
        return None  # "Zhang doesn't need the file": nobody else is a recipient
    said = [m for m in mentions if start <= m.start < stop]
    if any(m.kind == "self" for m in said):
        return None  # "Zhang, send me the file": the speaker again
    others = {m.ids[0] for m in said if recipient_as_need(tokens, m)} - not_them
    if len(others) != 1 or not any(_refers_back(tokens, m, item) for m in said):
        return None
    return others.pop()


def _refers_back(tokens: Sequence[Token], m: Mention, item: Mention) -> bool:
    """Whether ``m`` is "the <the same item>" or "it"/"that", nobody's."""
    if m.possessive:
        return False
    if m.kind == "pronoun":
        return tokens[m.start].word in _BACK_PRONOUNS
    if m.kind == "item" and m.ids == item.ids:
        return m.start > 0 and tokens[m.start - 1].word in _BACK
    return False
