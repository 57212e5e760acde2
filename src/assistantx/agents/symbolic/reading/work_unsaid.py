"""Work on an item asked for with no verb that says which: "can you do something with my prep
before it turns", "deal with my prep please" where the office both vacuum-seals and
blast-chills prep.

With no task word in the request, the frames stage reads it as the item going somewhere, and
for the requester's own item that asks "Who should get your prep?": a question about a move
nobody asked for. Where the office runs several operations on that item, the request is far
more likely one of them, and which is the requester's to say: the question names them
("Which should I do with your prep: vacuum seal or blast chill?"), and the answer ("vacuum
seal") is read as that work done to it (``with_work``). A
request that says its work ("vac pack my prep", "bring me my prep") or an item only one
operation takes is read as before. Nothing is done before the answer.

A vague verb said of the thing ("can you get my costume sorted", "sort out my costume", "deal
with my costume", "see to it") where one operation of the office takes it is the same doubt
between two physical acts: fetching the thing or having that work done. The reader had
fetched it. One short question names both ("Shall I bring you your costume, or have it
mended?"); the answer that says the work ("mended", "mend it") is read as that work done to
it, one that says bringing ("bring it", "just bring it") as the thing brought. Where no
operation takes the thing, the reading is as before.

The same vague work said as a participle right after the requester's own thing, under a verb
of needing or getting ("I need my bowl sorted before the crit", "can you get my contract
dealt with today"), wants work done to it, not the thing moved: the need or the "get" is no
fetch (fixer fix60g class 2: the reader brought the thing back). Where two or more of the
office's services take the thing, the question names them as above. The office's signable
paper counts signing, and stamping with its seal where it has one, among its services
("Which should I do with your document: copy, sign or seal?").
"""

from __future__ import annotations

import re
from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language
from assistantx.core.office import Office
from assistantx.core.task_schema import Task

WHICH_WORK = "Which should I do with your "
FETCH_OR_WORK = "Shall I bring you your "
_FETCH_OR = re.compile(r"^Shall I bring you your .+?, or have it (?P<done>[\w-]+)\?$")
# "sort out", "deal with", "see to": said of a thing, no work named
_VAGUE = tuple(tuple(p.split()) for p in english.entries("vague_work"))
# "my bowl *sorted*", "my contract *dealt with*": the work wanted, said after the thing
_VAGUE_DONE = tuple(tuple(p.split()) for p in english.entries("vague_done"))
# the answer that takes the bringing
_BRINGING = frozenset({"bring", "fetch", "brought", "bringing", "fetched"})
_POLITE_END = re.compile(r"[\s,]*(?:please|pls|thanks|thank you)?[\s.!?]*$", re.IGNORECASE)


def which_work(
    office: Office,
    tasks: Sequence[Task],
    mentions: Sequence[Mention],
    requester: str,
    tokens: Sequence[Token] = (),
) -> str | None:
    """The question which operation is meant, when no word of the request asks for any work
    (or only a verb of needing or getting, with vague work said after the thing) and its one
    task would only bring the requester's own item back to them."""
    if len(tasks) != 1:
        return None
    [task] = tasks
    if task.kind != "transfer" or task.item is None:
        return None
    if not (task.owner == task.recipient == requester) or task.source is not None:
        return None
    cues = [m for m in mentions if m.kind == "cue"]
    if cues and not (
        all(m.ids == ("give",) for m in cues) and _done_after(task.item, mentions, tokens)
    ):
        return None
    names = services_on(office, task.item)
    if len(names) < 2:
        return None
    name = office.item_type(task.item).name
    return f"{WHICH_WORK}{name}: {', '.join(names[:-1])} or {names[-1]}?"


def services_on(office: Office, item: str) -> list[str]:
    """The names of the office's services that take an item of type ``item``: its
    operations on it, and signing and sealing where it is the office's signable paper."""
    names = [
        op.name
        for op in office.operations
        if op.input == item and office.runnable(op.id) and not op.sends_out
    ]
    if item == office.signable_type():
        names.append("sign")
        if office.seal_tool() is not None:
            names.append("seal")
    return names


def _done_after(item: str, mentions: Sequence[Mention], tokens: Sequence[Token]) -> bool:
    """Whether a participle of vague work follows the requester's own ``item`` at once ("my
    bowl sorted", "my contract dealt with")."""
    words = [t.word for t in tokens]
    return any(
        m.kind == "item" and item in m.ids and tuple(words[m.end : m.end + len(p)]) == p
        for m in mentions
        for p in _VAGUE_DONE
    )


def with_work(text: str, answer: str) -> str:
    """The request with the answer to ``WHICH_WORK`` said as the work done to its item:
    "... my prep before it turns. vacuum seal it"."""
    work = _POLITE_END.sub("", answer.strip())
    return f"{text.rstrip(' .!?')}. {work} it"


def fetch_or_work(
    office: Office, tasks: Sequence[Task], tokens: Sequence[Token], requester: str
) -> str | None:
    """The question whether to fetch the requester's own thing or have the office's one work
    on it done, when a vague verb ("sort out", "deal with") is all the request says of it."""
    if len(tasks) != 1:
        return None
    [task] = tasks
    if task.kind != "transfer" or task.item is None:
        return None
    if not (task.owner == task.recipient == requester):
        return None
    words = [t.word for t in tokens]
    if not any(tuple(words[n : n + len(p)]) == p for p in _VAGUE for n in range(len(words))):
        return None
    ops = [
        op
        for op in office.operations
        if op.input == task.item and office.runnable(op.id) and not op.sends_out and op.verbs
    ]
    if len(ops) != 1:
        return None  # two or more: ``which_work`` asks which
    if len(services_on(office, task.item)) != 1:
        return None  # signing or sealing besides: ``which_work`` asks which
    name = office.item_type(task.item).name
    return f"{FETCH_OR_WORK}{name}, or have it {language.past_participle(ops[0].verbs[0])}?"


def with_fetch_or_work(office: Office, text: str, question: str, answer: str) -> str | None:
    """The request as the answer to ``FETCH_OR_WORK`` chose: the work said ("mended", "mend
    it") done to the thing, or bringing it ("bring it"); None where the answer says neither."""
    asked = _FETCH_OR.match(question)
    if asked is None:
        return None
    words = set(language.words(answer.lower()))
    done = asked.group("done").lower()
    verbs = {v for op in office.operations for v in op.verbs if language.past_participle(v) == done}
    said_work = done in words or bool(
        {f for v in verbs for f in (v, *language.verb_forms(v))} & words
    )
    # "get it mended" is the work; "just get it" the bringing
    said_bring = bool(words & _BRINGING) or ("get" in words and not said_work)
    if said_work == said_bring:
        return None
    if said_work:
        return f"{text.rstrip(' .!?')}. {sorted(verbs)[0]} it"
    return _vague_said(text, "bring me")


def _vague_said(text: str, instead: str) -> str:
    """``text`` with its vague verb said as bringing: "get my costume sorted" → "get my
    costume", "sort my costume out" and "deal with my costume" → "bring me my costume"."""
    if re.search(r"\bsorted\b", text, re.IGNORECASE):
        return re.sub(r"\s*\bsorted\b", "", text, count=1, flags=re.IGNORECASE)
    parted = re.sub(
        r"\bsort\s+(?P<x>(?:\w+\s+){0,3}?\w+)\s+out\b",
        rf"{instead} \g<x>",
        text,
        count=1,
        flags=re.IGNORECASE,
    )
    if parted != text:
        return parted
    return re.sub(
        r"\b(?:sort(?:ing)?(?:\s+out)?|deal(?:ing)?\s+with|dealt\s+with|see\s+to)\b",
        instead,
        text,
        count=1,
        flags=re.IGNORECASE,
    )
