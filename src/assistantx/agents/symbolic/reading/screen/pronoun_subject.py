"""A third person's pronoun as the subject of a need ("she needs the umbrella", "he could use
a ruler", "they want a calculator") means someone the message named before it, never the
speaker: the speaker says "I". Without this the reader dropped the pronoun and the need was
read as the speaker's own, so the thing was handed to the speaker (a wrong hand-over).

Two steps:

- ``named_subject`` (a rewrite before the pieces are judged): where exactly one colleague (not
  the speaker) is named before the pronoun ("Rose is soaked, she needs the umbrella"), the
  pronoun becomes that name, so the need is read as "Rose needs the umbrella" is (restated
  and asked).
- ``unnamed_subject`` (a rule of the screen): a piece opened by such a pronoun with nobody
  named before it is asked about ("Who do you mean by 'she'?"), never acted on; so is one
  after several colleagues where nothing else in the message is asked ("Rose and Mark are
  here, she needs the umbrella": "Rose Adeyemi or Mark Lindqvist?"). The answer names whom
  it means (``with_subject_answered``).

The same holds for "she"/"he" as the subject of a causative asked with a modal ("can she get
my report printed", ``asked_to_have.caused_for``): the thing is made for the one it means,
written as the name by ``rewrites.name_pronouns`` where one colleague was named before, and
asked about here where nobody was (fix59f class 1), never read as made for the speaker.

A pronoun in any other place ("take it to her", "could she have ...") is left to the stages
that read it (``rewrites.name_pronouns``, the frames)."""

from __future__ import annotations

import re
from collections.abc import Sequence

from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.subject_adverbs import is_adverb_before_verb
from assistantx.core import english, language
from assistantx.core.asked_to_have import caused_for
from assistantx.core.task_schema import Evidence

_PRONOUNS = ("she", "he", "they")
# the verbs a need is said with after its subject, besides the need phrases of the English
# data ("is after", "could use"); "'s"/"is" forms are written both ways
_NEED_VERBS = ("needs", "need", "wants", "want", "would like", "d like", "really needs")
# "she *really* / *definitely* / *still* needs": up to two words between the pronoun and the
# verb, each an adverb by the dictionary (``subject_adverbs``); one that denies ("she
# *hardly* needs") is no need, and leaves the pronoun unread here
_ADVERB_WORDS = 2
# what may stand before the pronoun at the start of its clause: the message's start, a
# sentence's or part's end, or a joining word ("Rose is soaked and she needs ...")
_OPENING = r"(?:^|(?<=[.,;:!?\-–—(])\s*|\b(?:and|but|so|now|plus)\s+)"

# a joining word before the pronoun ("and she needs"), and the marks that already end a part
_JOINED = re.compile(r"\s*\b(?:and|but|so|now|plus)\s+", re.IGNORECASE)
_PAUSES = frozenset(".,;:!?-–—(")

# what follows a need's verb when the need is no thing wanted: work to do ("she needs to stamp
# it": the request's own doer) or a thing said before ("she needs it today": the reason for
# the part that names it, read where that part is)
_NOT_A_THING = ("to", "it", "one", "them", "that", "this", "these", "those")


def _need_matches(text: str) -> list[re.Match[str]]:
    """The pronoun needs of ``text`` whose words before the verb, if any, are all adverbs."""
    return [m for m in _PRONOUN_NEED.finditer(text) if _adverbs_only(m)]


def _adverbs_only(match: re.Match[str]) -> bool:
    return all(is_adverb_before_verb(w.lower()) for w in (match.group("adverb") or "").split())


def _verb_pattern() -> str:
    # "asked for", "is asking for": a report of what was asked, not a need ("he asked for
    # the numbers" is news, "bring Hedda a ruler, she just asked for one" a reason)
    phrases = {
        p
        for p in (*_NEED_VERBS, *english.entries("need_phrases"))
        if not {"asked", "asking"} & set(p.split())
    }
    forms: list[str] = []
    for phrase in sorted(phrases, key=len, reverse=True):
        words = phrase.split()
        if words[0] in ("s", "d"):  # "'s after", "'d like": the contraction on the pronoun
            forms.append(r"['’]?" + words[0] + r"\s+" + r"\s+".join(map(re.escape, words[1:])))
            continue
        forms.append(r"\s+" + r"\s+".join(map(re.escape, words)))
    return "(?:" + "|".join(forms) + ")"


_PRONOUN_NEED = re.compile(
    _OPENING
    + r"(?P<pronoun>"
    + "|".join(_PRONOUNS)
    + r")(?P<adverb>(?:\s+[^\W\d_]+){1,"
    + str(_ADVERB_WORDS)
    + r"}?)??(?P<verb>"
    + _verb_pattern()
    + r")\b(?!\s+(?:"
    + "|".join(_NOT_A_THING)
    + r")\b)",
    re.IGNORECASE,
)


def _colleagues(terms: Terms, text: str, requester: str) -> list[str]:
    """The colleagues (not the speaker) that ``text`` names, in order."""
    return [p for p in terms.named(terms.lex.read(text), "person") if p != requester]


def named_subject(terms: Terms, text: str, requester: str) -> tuple[str, list[Evidence]]:
    """``text`` with the pronoun subject of a need, or of a causative asked with a modal
    ("can she get my report printed"), written as the one colleague it means."""
    found: list[Evidence] = []

    def meant(match: re.Match[str]) -> str:
        if not _adverbs_only(match):
            return match.group(0)  # "she hardly needs": no need, and no pronoun of one
        before = set(_colleagues(terms, text[: match.start("pronoun")], requester))
        opening = _opening(text, match)
        if len(before) > 1:
            # whom it means is the frames' (or the rule's) to ask, on a piece of its own
            return opening + match.group(0)[match.start("pronoun") - match.start() :]
        if not before:
            return match.group(0)  # nobody named: asked (``unnamed_subject``)
        who = next(iter(before))
        name = terms.office.person(who).name
        verb = match.group("verb")
        if match.group("pronoun").lower() == "they":
            # "they need" of one colleague: the singular verb of the name
            verb = re.sub(r"\bneed\b", "needs", re.sub(r"\bwant\b", "wants", verb))
            verb = re.sub(r"^['’]?re\b", " is", verb)
        said = opening + name + (match.group("adverb") or "") + verb
        found.append(
            Evidence(words=match.group(0).strip(), meaning=f"{name}'s need, said by a pronoun")
        )
        return said

    text = _PRONOUN_NEED.sub(meant, text)
    for caused in reversed(_caused_matches(text)):
        # "we've a new volunteer, Rose, starting tomorrow. can she get a badge laminated": the
        # thing is made for the one colleague named before the pronoun
        before = set(_colleagues(terms, text[: caused.start("pronoun")], requester))
        if len(before) != 1:
            continue  # none, or several: asked (``unnamed_subject``)
        name = terms.office.person(next(iter(before))).name
        found.append(Evidence(words=caused.group(0), meaning=f"made for {name}, said by a pronoun"))
        text = text[: caused.start("pronoun")] + name + text[caused.end("pronoun") :]
    return text, found


def _opening(text: str, match: re.Match[str]) -> str:
    """What stands before the pronoun of ``match``, a joining word written as a pause: in
    "Chen is cold and she needs a coffee" the need is a clause of its own, not part of the
    state said before it; the pause keeps it a piece of its own, read as "Chen needs a
    coffee" is (the joining word folded it into the statement: "Noted")."""
    said = match.group(0)[: match.start("pronoun") - match.start()]
    if not _JOINED.fullmatch(said):
        return said
    return " " if text[: match.start()].rstrip()[-1:] in _PAUSES else ", "


# "can she get my report printed": a modal, then the pronoun the causative is asked of
_CAUSED_SUBJECT = re.compile(
    r"\b(?P<modal>"
    + "|".join(sorted(english.words("request_modals"), key=len, reverse=True))
    + r")\s+(?P<pronoun>she|he)\b",
    re.IGNORECASE,
)


# "can he have a coffee", "could she borrow the projector": the verbs by which a thing is
# asked for whom a modal's pronoun means (as a causative is, above)
_HAVING = frozenset({"have", "borrow", "use"})
# what after such a verb is no thing asked for ("can she have a look", "could he use a hand"
# are help, and "can he have it" a thing said before: read where it is named)
_NOT_HAD = frozenset({"a look", "a go", "a hand", "a word", "a think", "a chat", "a break"})


def _had_for(after: Sequence[str]) -> bool:
    """Whether ``after`` (the words past "<modal> she/he") asks for a thing for the one the
    pronoun means: "have a coffee", "please borrow my stapler"."""
    words = list(after[1:] if after[:1] == ["please"] else after)
    if len(words) < 2 or words[0] not in _HAVING:
        return False
    if " ".join(words[1:3]) in _NOT_HAD or words[1] in ("to", "it", "them", "that", "this"):
        return False
    return True


def _caused_matches(text: str) -> list[re.Match[str]]:
    """The "<modal> she/he" of ``text`` that a causative follows ("can she get my report
    printed": the thing is made for the one the pronoun means), or a thing had, borrowed or
    used ("can he have a coffee": the coffee is for the one the pronoun means, never the
    speaker's)."""
    out: list[re.Match[str]] = []
    for m in _CAUSED_SUBJECT.finditer(text):
        after = language.words(text[m.end() :])
        if caused_for(m.group("modal").lower(), after) or _had_for(after):
            out.append(m)
    return out


def unnamed_subject(terms: Terms, msg: Message, piece: Piece, requester: str) -> Finding | None:
    """A need whose subject is "she"/"he"/"they" with nobody named before it, or a causative
    asked of "she"/"he" ("can she get my report printed"): asked whom the pronoun means, never
    read as the speaker's own need."""
    match = next(iter(_need_matches(piece.text)), None)
    if match is None:
        caused = next(iter(_caused_matches(piece.text)), None)
        return None if caused is None else _whom_caused(terms, msg, piece, requester, caused)
    if piece.text[: match.start("pronoun")].strip(" ,.-–—;:!?"):
        return None  # not the piece's own subject ("if she needs it" is a condition)
    before = {
        p
        for earlier in msg.pieces
        if earlier.end <= piece.start
        for p in terms.named(earlier.lexed, "person")
        if p != requester
    }
    asked = any(p.acts.request or p.acts.imperative for p in msg.pieces if p is not piece)
    if len(before) == 1 or (before and asked):
        # one named: written as the name before (``named_subject``); several beside a
        # request ("take Mark's ruler to Grace, she needs it"): the reason for it
        return None
    return _who_asked(terms, piece, match.group("pronoun"), before)


def _whom_caused(
    terms: Terms, msg: Message, piece: Piece, requester: str, caused: re.Match[str]
) -> Finding | None:
    """Whom the causative's "she"/"he" means, asked where no colleague, or several, were
    named before it (one named: written as the name, ``rewrites.name_pronouns``)."""
    before = {
        p
        for earlier in msg.pieces
        if earlier.end <= piece.start
        for p in terms.named(earlier.lexed, "person")
        if p != requester
    } | set(_colleagues(terms, piece.text[: caused.start("pronoun")], requester))
    if len(before) == 1:
        return None
    return _who_asked(terms, piece, caused.group("pronoun"), before)


def _who_asked(terms: Terms, piece: Piece, said: str, before: set[str]) -> Finding:
    """The question whom the pronoun ``said`` means, listing the colleagues named before it."""
    question = f"Who do you mean by {said!r}? Please tell me their name."
    if before:
        names = " or ".join(terms.office.person(p).name for p in sorted(before))
        question = f"Who do you mean by {said!r}: {names}?"
    return Finding("which", piece, f"whom {said!r} means is asked", message=question)


_ASKED = re.compile(r"^Who do you mean by '(?P<pronoun>\w+)'")
_ME = frozenset({"me", "i", "myself", "mine"})


def with_subject_answered(
    terms: Terms, text: str, requester: str, question: str, answer: str
) -> str | None:
    """The request with the pronoun ``unnamed_subject`` asked about written as the colleague
    the answer names ("she needs the umbrella" → "Who do you mean by 'she'?" → "Rose": "Rose
    needs the umbrella"); "me" makes it the speaker's own need. None where the question was
    another's or the answer names nobody, or several (the question stays open)."""
    asked = _ASKED.match(question)
    if asked is None or asked.group("pronoun").lower() not in _PRONOUNS:
        return None
    said = asked.group("pronoun").lower()
    match = next((m for m in _need_matches(text) if m.group("pronoun").lower() == said), None)
    if match is None:
        return _caused_answered(terms, text, requester, said, answer)
    words = terms.lex.read(answer).tokens
    people = set(terms.named(terms.lex.read(answer), "person"))
    verb = match.group("verb")
    if people == {requester} or (not people and [t.word for t in words] in ([w] for w in _ME)):
        name = "I"
        verb = re.sub(r"\bneeds\b", "need", re.sub(r"\bwants\b", "want", verb))
    elif len(people) == 1:
        name = terms.office.person(next(iter(people))).name
        verb = re.sub(r"\bneed\b", "needs", re.sub(r"\bwant\b", "wants", verb))
    else:
        return None
    start, end = match.start("pronoun"), match.end("verb")
    return text[:start] + name + (match.group("adverb") or "") + verb + text[end:]


def _caused_answered(terms: Terms, text: str, requester: str, said: str, answer: str) -> str | None:
    """The causative's pronoun asked about (``_whom_caused``) written as the colleague the
    answer names ("can she get my report printed" → "Zhang": "can Zhang Wei get my report
    printed"); "me" makes it the speaker's ("can I get ..."); None otherwise."""
    match = next((m for m in _caused_matches(text) if m.group("pronoun").lower() == said), None)
    if match is None:
        return None
    words = terms.lex.read(answer).tokens
    people = set(terms.named(terms.lex.read(answer), "person"))
    if people == {requester} or (not people and [t.word for t in words] in ([w] for w in _ME)):
        name = "I"
    elif len(people) == 1:
        name = terms.office.person(next(iter(people))).name
    else:
        return None
    return text[: match.start("pronoun")] + name + text[match.end("pronoun") :]
