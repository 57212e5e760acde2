""" "it" with nothing to refer to: "can you print it and bring it over", the first thing said,
names no item, no file, and nobody's thing. "it" points back at something said; with nothing
said, which file is meant is asked, never guessed as the requester's own. "this" / "that"
point at something at hand (a file attached, a paper held out) and keep their reading, and so
does every message that names a thing ("print my shoot and bring it over"), in words of the
office or not: "print the press release and take it to Ngozi" says what "it" is (a thing put
after the work's verb with its article) and sends it on to a colleague: the speaker's own to
send, read as "print the press release" alone is (fix169a class 2: it asked which file "it"
was). Brought to the speaker ("print the meeting note and bring it to me") whose it is stays
asked."""

from __future__ import annotations

import re

from assistantx.agents.symbolic.reading.lexicon import Lexed
from assistantx.core.office import Office
from assistantx.core.receiving_place import ahead_at, names_receiving_place
from assistantx.core.task_schema import Task

# Words that refer back to something said before, never to something at hand.
_ANAPHORS = frozenset({"it", "them"})
# The far demonstratives said alone as a work's object ("print *that* out for me"): like "it",
# they point back at something said; with nothing said, which file is asked ("this"/"these"
# point at something at hand and keep their reading)
_FAR = frozenset({"that", "those"})
_ANCHORS = frozenset({"item", "facility", "place"})
WHICH_FILE = "Which file do you mean by"
_BARE_POSSESSIVE = re.compile(r"['’]s$|s['’]$")
_OTHERS_POSSESSIVES = frozenset({"his", "her", "their"})
# The articles that open a noun phrase said as the work's object ("print *the* press release")
_ARTICLES = frozenset({"the", "a", "an", "that", "these", "those"})
# What ends the object's phrase ("... and take it"), and words that tie more to it
_JOINS = frozenset({"and", "then", "&", "+", ",", "plus"})
# The particles a work's verb may take after "it" ("print it *out*", "run them *off*")
_PARTICLES = frozenset({"out", "off", "up", "over", "through", "again", "now", "quickly"})
_LINKS = frozenset({"for", "from", "of", "by", "with", "about", "to", "at", "in", "on", "re"})


def unanchored_it(office: Office, whole: Lexed, tasks: list[Task]) -> str | None:
    """The question to ask where the tasks' file is only "it" and the message names nothing
    it could be; None where it names something, or a task is no file's."""
    back = _pointing_back(whole)
    if not back:
        return None
    purpose = _purpose_after_it(whole)
    for m in whole.mentions:
        if m.start in purpose:
            continue  # "print it off for the induction table": what it is for, not what it is
        if m.kind in _ANCHORS or (m.kind in ("person", "self") and m.possessive):
            return None  # "print my shoot and bring it over", "Kwame's file, print it"
        if m.kind == "pronoun" and m.start not in back:
            return None  # "print this": at hand
    if not tasks or any(t.item is None for t in tasks):
        return None
    if not all(office.item_type(t.item).kind == "electronic" for t in tasks if t.item):
        return None
    if _object_said(whole) and all(t.recipient != t.owner for t in tasks):
        # "print the press release and take it to Ngozi": "it" is the release, the speaker's
        # to send on; brought to the speaker ("print the meeting note and bring it to me")
        # it may be anyone's, and whose is still asked
        return None
    said = whole.tokens[min(back)].text
    kinds = list(dict.fromkeys(office.item_type(t.item).name for t in tasks if t.item))
    return f"{WHICH_FILE} {said!r}? Please tell me whose {' or '.join(kinds)} it is."


def _pointing_back(whole: Lexed) -> frozenset[int]:
    """Where a word that points back at something said stands: "it"/"them" anywhere, and
    "that"/"those" said alone right after a work's verb ("print that (out)"); a far
    demonstrative before its noun ("print that report") or after any other word ("tell Wang
    that ...") is none."""
    tokens = whole.tokens
    cues = {m.end for m in whole.mentions if m.kind == "cue"}
    named = {m.start for m in whole.mentions if m.kind != "word"}
    back = {n for n, t in enumerate(tokens) if t.word in _ANAPHORS}
    for n, t in enumerate(tokens):
        if t.word in _FAR and n in cues and n + 1 not in named:
            back.add(n)
    return frozenset(back)


def _purpose_after_it(whole: Lexed) -> frozenset[int]:
    """Where the phrase of whom or what "it" is for stands, right after it ("print it (off)
    *for the induction table*", "... *for Zhang's 3pm slot*"): a place, a thing or a person's
    thing named there says what the work is for, never which file "it" is; read as the
    file's anchor, the speaker's own file was printed unasked. The phrase runs to the next
    join ("print it for me, the budget file": the file is said after the comma)."""
    tokens = whole.tokens
    inside: set[int] = set()
    back = _pointing_back(whole)
    for n, _ in enumerate(tokens):
        if n not in back:
            continue
        k = n + 1
        while k < len(tokens) and tokens[k].word in _PARTICLES:
            k += 1  # "print it *off* for ..."
        if k >= len(tokens) or tokens[k].word != "for":
            continue
        k += 1
        while k < len(tokens) and tokens[k].word not in _JOINS:
            inside.add(k)
            k += 1
            if k < len(tokens) and (tokens[k].after_pause or tokens[k].opens):
                break  # a comma or a new sentence ends it
    return frozenset(inside)


def _object_said(whole: Lexed) -> bool:
    """Whether a work's verb is followed by an article and a plain word before the first
    "it"/"them": the thing the verb works on, said in words the office need not know ("print
    the press release and take it to Ngozi"); a name or a pronoun after the article is none."""
    first = min(_pointing_back(whole))
    plain = {m.start for m in whole.mentions if m.kind == "word"}
    for m in whole.mentions:
        if m.kind != "cue" or m.end + 1 >= first or whole.tokens[m.end].word not in _ARTICLES:
            continue
        phrase = []
        for k in range(m.end + 1, first):
            if whole.tokens[k].word in _JOINS:
                break
            phrase.append(k)
        # "the quote for Riverside House": a phrase with more than its noun's words (whom
        # or what it is for) is no plain name of the thing; what it is is still asked
        if phrase and all(k in plain and whole.tokens[k].word not in _LINKS for k in phrase):
            return True
    return False


def with_antecedent(text: str, answer: str, kind: str = "") -> str:
    """The request with the answer to ``WHICH_FILE`` in the place of its first "it"
    ("print it and bring it over" + "Kwame's shoot" → "print Kwame's shoot and bring it
    over"): read as the request's own object, not as a request of its own. A bare
    possessive ("Kwame's") is completed with ``kind``, the file the question asked about."""
    said = answer.strip().rstrip(" .!?")
    if kind and _BARE_POSSESSIVE.search(said):
        said = f"{said} {kind}"  # "Kwame's" → "Kwame's shoot file": the kind asked about
    # "it"/"them" where said, else the "that" the question was asked of ("print that out")
    for words in (_ANAPHORS, _FAR):
        pattern = r"\b(?:" + "|".join(sorted(words)) + r")\b"
        if re.search(pattern, text, flags=re.IGNORECASE):
            return re.sub(pattern, lambda _: said, text, count=1, flags=re.IGNORECASE)
    return text


def anothers_it(
    office: Office, whole: Lexed, tasks: list[Task], requester: str, named_once: str | None
) -> str | None:
    """ "Tam's seating chart is done, can you print it for me?", "Tam finished her seating
    chart, print it": the tasks read "it" as the requester's own file, but the message names
    the thing only as another colleague's (a possessive, or "his"/"her" of the one colleague
    named) and never as the requester's ("my", or "from me": "Wang needs the minutes from me,
    send them to her" is the requester's file): whose it is, that colleague; None otherwise.
    A possessive of the place "it" is left at ("print the rota and stick it on Tam's desk")
    is the place's, whom it is left for, never whose the thing is (fix59f class 2)."""
    words = {t.word for t in whole.tokens}
    if not words & _ANAPHORS or not tasks:
        return None
    if not all(t.item and office.item_type(t.item).kind == "electronic" for t in tasks):
        return None
    if any(t.owner != requester for t in tasks):
        return None
    owners: set[str] = set()
    for m in whole.mentions:
        if m.kind == "self" and m.start > 0 and whole.tokens[m.start - 1].word == "from":
            return None  # "Wang needs the minutes from me": they come from the requester
        if not m.possessive or _left_at_their_place(whole, m.start):
            continue
        if m.kind == "self":
            return None  # "my seating chart": the requester's own, as read
        if m.kind == "person":
            owners.update(m.ids)
        elif m.kind == "pronoun" and whole.tokens[m.start].word in _OTHERS_POSSESSIVES:
            if named_once is None:
                return None
            owners.add(named_once)
    owners.discard(requester)
    return next(iter(owners)) if len(owners) == 1 else None


def _left_at_their_place(whole: Lexed, at: int) -> bool:
    """Whether the possessive at token ``at`` names the place "it" is left at ("stick it *on
    Tam's* desk", "put them down in her tray"), not where a thing lies ("the chart on Tam's
    desk", "the one on Tam's desk"): "it"/"them" just before the place's preposition."""
    tokens = whole.tokens
    if at == 0 or at + 1 >= len(tokens):
        return False
    before, after = tokens[at - 1].word, tokens[at + 1].word
    ahead = ahead_at(tokens, at - 1)
    if not set(ahead.words) & _ANAPHORS:
        return False
    return names_receiving_place(before, after, ahead)
