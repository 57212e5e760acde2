"""A person's work said not done yet, beside a request: "Dr Hale still hasn't signed the new
policy. Can you take my copy to him and bring it back once he has?", "Pat hasn't stamped my
lease yet, can you get that done?". The statement says what the request is for: the work
still to be done by that colleague on the thing, so it is read as an obligation would be
("Dr Hale needs to sign the new policy"), which the later stages read as that work by them,
the thing taken to them and back (``obligation``; the hand-over to them is its way there).

Only a colleague named as the subject, a verb of a person's work (sign, stamp ...), and a
request in a later sentence or part of the message: said alone, it is a statement, and
nothing is moved on it."""

from __future__ import annotations

import re

from assistantx.agents.symbolic.reading.obligation import PERSON_WORK
from assistantx.agents.symbolic.reading.screen.english import split_words
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import language
from assistantx.core.task_schema import Evidence

_UNDONE = re.compile(
    r"(?P<still>\bstill\s+)?\b(?:has|have)(?:n['’]?t|\s+not)\s+(?:yet\s+)?"
    r"(?:(?:got|gotten)\s+(?:a)?round\s+to\s+)?(?P<work>[a-z]+)\b"
    r"(?P<said>[^.!?;,\n]*?)(?P<yet>\s+yet)?(?=\s*[.!?;,\n]|\s+[-–—]+\s|\s*$)",
    re.IGNORECASE,
)
_SENTENCE_START = re.compile(r"[.!?;\n]\s*")


def undone_work(terms: Terms, text: str) -> tuple[str, list[Evidence]]:
    """``text`` with each such statement said as the obligation it leaves, and why."""
    evidence: list[Evidence] = []
    out = text
    for m in reversed(list(_UNDONE.finditer(text))):
        lemma = next(
            (v for v in sorted(language.verb_lemmas(m.group("work").lower())) if v in PERSON_WORK),
            None,
        )
        if lemma is None:
            continue
        starts = [s.end() for s in _SENTENCE_START.finditer(text, 0, m.start())]
        subject = text[starts[-1] if starts else 0 : m.start()].strip()
        if not _a_colleague(terms, subject, m.group(0)):
            continue
        said = m.group("said")
        papers = {x.ids[0] for x in terms.lex.read(said).mentions if x.kind == "item"}
        if not papers:  # "hasn't signed the new policy": a paper the office names otherwise
            papers = {t.id for t in terms.office.item_types if t.signable}
            if len(papers) == 1:  # the office's one paper to sign, by its own name
                said = f" the {terms.office.item_type(next(iter(papers))).name}"
        rest = out[m.end() :]
        owns = []
        for phrase in _copies_of(terms, papers):
            # "take my copy to him": the requester's own paper, never a photocopy made
            pattern = re.compile(rf"\bmy\s+{re.escape(phrase)}\b", re.IGNORECASE)
            if pattern.search(rest):
                rest = pattern.sub("mine", rest)
                owns.append(Evidence(words=f"my {phrase}", meaning="my own paper"))
        if not _asked_after(terms, rest, papers):
            continue
        start = m.start("still") if m.group("still") else m.start()
        evidence += owns
        out = f"{out[:start]}needs to {lemma}{said}{rest}"
        evidence.append(
            Evidence(words=m.group(0).strip(), meaning=f"still to {lemma}: what is asked for")
        )
    return out, evidence


def _copies_of(terms: Terms, papers: set[str]) -> list[str]:
    """The names of a product made from one of ``papers`` ("copy", "photocopy" of the
    policy), longest first: said as "my ...", the requester's own paper is meant."""
    office = terms.office
    found: set[str] = set()
    for op in office.operations:
        if op.product and op.input in papers and office.item_type(op.product).kind == "product":
            t = office.item_type(op.product)
            found |= {t.name, *t.synonyms}
    return sorted(found, key=len, reverse=True)


def _a_colleague(terms: Terms, subject: str, undone: str) -> bool:
    """Whether the words are one colleague's name, nothing more ("Pat", "Dr Hale"): read
    with the statement's verb after them (``undone``), whose subject a name that is also a
    word is ("mark hasn't signed it": Mark, never the word "mark")."""
    if not subject:
        return False
    said = len(terms.lex.read(subject).tokens)
    lexed = terms.lex.read(f"{subject} {undone}")
    named = [
        m
        for m in lexed.mentions
        if m.start < said and (m.kind != "word" or m.ids[0] not in _TITLES)
    ]
    return (
        len(named) == 1
        and named[0].kind == "person"
        and len(named[0].ids) == 1
        and not named[0].possessive
    )


_TITLES = frozenset({"dr", "mr", "mrs", "ms", "miss", "prof", "professor"})


def _asked_after(terms: Terms, rest: str, papers: set[str]) -> bool:
    """Whether the first later request of the message asks for nothing but what the
    statement leaves undone: it names no thing but those papers ("take mine to him", "can
    you get that done?") and no service of the office ("make me a copy of it" asks for other
    work: the statement is then its context, as before)."""
    for part in re.split(r"[.!?;,\n]+|\s[-–—]+\s", rest):
        words = split_words(part)
        if not words or not terms.acts.request(words):
            continue
        items = [x.ids[0] for x in terms.lex.read(part).mentions if x.kind == "item"]
        return all(i in papers for i in items) and not set(words) & terms.service_verbs
    return False
