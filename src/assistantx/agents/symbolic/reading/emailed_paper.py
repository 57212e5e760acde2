"""A paper asked for, then to be sent electronically: "could I have Wang's report? just email
it to me". The requester named a channel: an electronic copy, never the paper carried over.

The paper is an item of the office that is paper by its own data (signable, or named with an
everyday noun of a paper: ``paper_nouns``), said as a colleague's; the later clause sends
"it"/"that" by a verb of electronic sending (``electronic_sending``) to the speaker or
nobody named. What the office can do decides, read from its operations, never its names:

- an operation that takes that paper and makes an electronic thing (its product is an
  electronic item, or named as one: "scanned copy", "PDF") makes the copy: the send is read
  as that operation's verb ("... just scan it to me"), done with the owner's yes as any work
  on a colleague's paper;
- none, where the office keeps its papers' electronic files too (a generic electronic file
  type, and the paper one of the personal things a sending verb reads as that file: "email
  me Wang's report" is Wang's file): the send is that file's ("get Chen's report and send
  it to me" → "forward Chen's report to me"), asked of the owner as any file is;
- none else: said, and asked whether to bring the paper instead ("I can't email a paper
  document here. Shall I bring Wang's report to you?"); a yes reads the send as "bring".

The send is a later clause (after a stop or a comma), or one joined by "and"/"then" with
nothing named between ("get Chen's report and email it to me"). The colleague may be said by
a possessive pronoun after the one asked ("ask Wang for her report and email it to me").
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from assistantx.agents.symbolic.reading.aligned import aligned_reading
from assistantx.agents.symbolic.reading.lexicon import Lexicon, Mention
from assistantx.agents.symbolic.reading.tokens import Token, clause_start
from assistantx.core import english, language
from assistantx.core.office import Office

_SENDING = english.words("electronic_sending")
_BACK = frozenset({"it", "that", "this"})
_TO = frozenset({"to", "for"})
_JOINS = english.words("emailed_paper_joins")
_FILLERS = english.words("emailed_paper_fillers")
_OWNER_PRONOUNS = english.words("others_possessives")
_PAPER_NOUNS = english.words("paper_nouns")
_ELECTRONIC_WORDS = english.words("electronic_formats") | english.words("electronic_picks")
# who a send is told of ("she emailed it"), and the words said between them ("she already
# sent it")
_SUBJECTS = frozenset({"i", "we", "he", "she", "they", "someone", "somebody"})
_TOLD_ADVERBS = frozenset({"already", "just", "accidentally", "mistakenly", "wrongly", "also"})
BRING = "bring"  # the send read as the paper brought, on a yes
FORWARD = "forward"  # the send read as the paper's electronic file forwarded


@dataclass(frozen=True)
class EmailedPaper:
    """Where the send verb stands in the text, and what is to be said in its place."""

    start: int  # character span of the send verb
    end: int
    verb: str  # the verb said ("email")
    thing: str  # the paper as said ("Wang's report")
    paper: str  # the paper's type name ("document")
    operation_verb: str | None  # the office's verb that makes an electronic copy ("scan")
    clause_end: int  # where the clause of the send ends (its last word's end)
    asked: int  # where the clause asking for the paper starts
    to: str | None  # the colleague the send names ("email it to Zhang"); None: the speaker
    as_file: bool = False  # the office reads the paper sent as its electronic file

    def with_verb(self, text: str, verb: str) -> str:
        """The request and its send said as one with ``verb``, for the speaker ("scan Wang's
        report for me", "bring Wang's report to me"): "over", "across" and the like say no
        more than that."""
        to = "to" if verb in (BRING, FORWARD) else "for"
        whom = self.to or "me"
        return f"{text[: self.asked]}{verb} {self.thing} {to} {whom}{text[self.clause_end :]}"

    @property
    def question(self) -> str:
        whom = self.to or "you"
        return (
            f"I can't {self.verb} a paper {self.paper} here. Shall I bring {self.thing} to {whom}?"
        )


def emailed_paper(lex: Lexicon, text: str, requester: str) -> EmailedPaper | None:
    """The paper of ``text`` sent electronically by a later clause (see the module)."""
    spans, tokens, mentions = aligned_reading(lex, text)
    if spans is None:
        return None
    office = lex.office
    for n, opener in enumerate(mentions[:-1]):
        item = mentions[n + 1]
        owner = _owner(tokens, mentions, n)
        if owner is None:
            continue
        if item.kind != "item" or item.start != opener.end or len(item.ids) != 1:
            continue
        copy_verb = _copy_verb(office, item.id)
        if copy_verb is None and not _is_paper(office, item.id):
            continue  # a paper by its data, or by the office's scan of it
        found = _sending_back(tokens, mentions, item.end, requester)
        if found is None:
            continue
        verb, clause_end, to = found
        thing = text[spans[opener.start][0] : spans[item.end - 1][1]]
        if opener.kind == "pronoun":  # "ask Wang for her report": Wang's
            noun = text[spans[item.start][0] : spans[item.end - 1][1]]
            thing = f"{office.person(owner).name}'s {noun}"
        said = tokens[verb].word
        return EmailedPaper(
            spans[verb][0],
            spans[verb][1],
            said,
            thing,
            office.item_type(item.id).name,
            copy_verb,
            spans[clause_end - 1][1],
            spans[clause_start(tokens, opener.start)][0],
            office.person(to).name if to is not None else None,
            copy_verb is None and _sent_as_file(office, item.id),
        )
    return None


def _owner(tokens: Sequence[Token], mentions: Sequence[Mention], n: int) -> str | None:
    """The colleague whose thing mention ``n`` opens: a colleague's possessive ("Wang's"), or
    a possessive pronoun after the one colleague named before it in its clause ("ask Wang
    for her report"); None where it is neither."""
    opener = mentions[n]
    if opener.kind == "person":
        return opener.id if opener.possessive and len(opener.ids) == 1 else None
    if opener.kind != "pronoun" or tokens[opener.start].word not in _OWNER_PRONOUNS:
        return None
    start = clause_start(tokens, opener.start)
    people = [m for m in mentions[:n] if m.start >= start and m.kind == "person"]
    if len(people) != 1 or len(people[0].ids) != 1 or people[0].possessive:
        return None
    return people[0].id


def _sent_as_file(office: Office, type_id: str) -> bool:
    """Whether a sending verb reads the office's paper as its electronic file ("email me
    Wang's report": Wang's file): the office has an electronic file type, and the paper is
    one of the personal things (``reading._kinds``, a personal thing sent)."""
    return office.file_type() is not None and office.item_type(type_id).kind == "personal"


def _is_paper(office: Office, type_id: str) -> bool:
    """Whether the office's item is a paper: one signs it, or it is named as a paper."""
    t = office.item_type(type_id)
    if not t.physical or t.kind == "product":
        return False
    names = {w for n in (t.name, *t.synonyms) for w in n.lower().split()}
    return t.signable or bool(names & _PAPER_NOUNS)


def _sending_back(
    tokens: Sequence[Token], mentions: Sequence[Mention], end: int, requester: str
) -> tuple[int, int, str | None] | None:
    """The token of the electronic send of "it" in a later clause ("just email it to me",
    "message it over", "email it to Zhang"), the clause's end and the colleague it names
    after "to"/"for" (None: the speaker); None where there is none."""
    at = end
    while at < len(tokens) and not (tokens[at].opens or tokens[at].after_pause):
        if tokens[at].word in _JOINS and _sends_next(tokens, at + 1):
            # "... and email it to me": a clause of its own, after nothing else named
            if any(end <= m.start < at and m.kind in ("item", "person") for m in mentions):
                return None  # "get Wang's report from Zhang and send it": read as before
            break
        at += 1
    stop = at + 1
    while stop < len(tokens) and not (tokens[stop].opens or tokens[stop].after_pause):
        stop += 1
    said = [m for m in mentions if at <= m.start < stop]
    if any(m.kind in ("item", "place", "facility") for m in said):
        return None  # "email it and the file": a request of its own
    people = [m for m in said if m.kind == "person"]
    to: str | None = None
    if people:
        m = people[0]
        before = tokens[m.start - 1].word if m.start > 0 else ""
        if len(people) > 1 or len(m.ids) != 1 or m.possessive or before not in _TO:
            return None  # "email it to Zhang and Hu", "email Zhang's": read as before
        to = None if m.id == requester else m.id
    for i in range(at, stop - 1):
        if tokens[i].word in _SENDING and tokens[i + 1].word in _BACK:
            if _told_of(tokens, mentions, i):
                return None
            return i, stop, to
    return None


def _sends_next(tokens: Sequence[Token], at: int) -> bool:
    """Whether the words from ``at`` send "it" electronically, after fillers ("then just
    email it")."""
    while at < len(tokens) - 1 and tokens[at].word in _FILLERS:
        at += 1
    return at < len(tokens) - 1 and tokens[at].word in _SENDING and tokens[at + 1].word in _BACK


def _told_of(tokens: Sequence[Token], mentions: Sequence[Mention], verb: int) -> bool:
    """Whether the send at ``verb`` is told of its subject, said right before it ("she
    emailed it to the wrong person", "Zhang already sent it"): what happened to the paper,
    the request's back-story, never a send asked for (fix201b class 4: before, "Could you get
    Wang's report file for me? She emailed it to the wrong person." asked whether to bring
    the paper, a question the requester could only answer no)."""
    k = verb - 1
    while k >= 0 and tokens[k].word in _TOLD_ADVERBS:
        k -= 1
    if k < 0:
        return False
    if tokens[k].word in _SUBJECTS:
        return True
    return any(
        m.kind == "person" and not m.possessive and m.end == k + 1 for m in mentions
    ) and language.is_past_verb(tokens[verb].word)


def _copy_verb(office: Office, paper: str) -> str | None:
    """The verb of an operation that makes an electronic thing of ``paper`` and that a
    facility of the office runs; None where the office has none."""
    run = {op for f in office.facilities for op in f.operations}
    for op in office.operations:
        if op.input != paper or op.product is None or op.id not in run or not op.verbs:
            continue
        product = office.item_type(op.product)
        named = {w for n in (product.name, *product.synonyms) for w in n.lower().split()}
        if product.electronic or named & _ELECTRONIC_WORDS:
            return op.verbs[0]
    return None
