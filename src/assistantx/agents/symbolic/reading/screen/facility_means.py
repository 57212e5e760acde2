"""A send-out facility named as the means: "send my form via the courier desk to Leeds City
Council", "put my letter in the post bag for Acme Ltd, Hull", "could my letter go in the post
bag to HMRC?", "can it go out with the courier today?". The facility (by its name or one of
its synonyms) or the means its one send-out service's name says ("send by courier":
"courier") stands where a verb of sending, putting or going takes its means ("via", "in",
"with", "through"): the request is that service's, read as "<its verb> my form to ...". The
destination keeps its words ("for Acme Ltd, Hull" is where it goes); with none said the
service asks where, as it always does. Taking a thing *to* the facility ("take my form to
the courier desk") names no means and is read as before; so is a facility that runs any
service besides its one send-out (it names no one service)."""

from __future__ import annotations

import re

from assistantx.agents.symbolic.reading.destination import means_words
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import language
from assistantx.core.office import Office, Operation
from assistantx.core.task_schema import Evidence

# The verbs that send or put a thing somewhere by a means ("send it via ...", "put it in
# ..."), and those of a thing going by one ("can it go out with ...").
_SENDING = r"send|sends|sent|put|pop|drop|get|stick|slip"
_GOING = r"go|goes|going|went"
_ON_ITS_WAY = r"(?:\s+(?:out|off|back|away|over))?"
_BY = r"(?:via|through|in|into|with|using|by)"
# A thing said with whose it is ("my letter", "this form", "Dev's contract", "it")
# (its words never "to" or "for": "send my proof to Tomas with the courier bag" sends nothing
# by the courier)
_THING = (
    r"(?:(?:this|these|that|those|my|our|the|[^\W\d_][\w-]*['’]s)"
    r"(?:\s+(?!(?:to|for)\b)[\w-]+){1,3}?|it|them)"
)
_ASKED = r"(?:(?:can|could|would|will|may|might)\s+)"


def facility_means(terms: Terms, text: str) -> tuple[str, list[Evidence]]:
    """``text`` with a send-out facility said as the means read as its service's request."""
    for phrase, op in _means_phrases(terms.office):
        said = r"\s+".join(re.escape(w) for w in phrase.split())
        means = rf"\s+{_BY}\s+(?:the\s+|our\s+)?{said}\b"
        sent = re.compile(
            rf"\b(?:{_SENDING})\s+(?P<thing>{_THING}){_ON_ITS_WAY}{means}(?P<rest>[^.!?;]*)",
            re.IGNORECASE,
        )
        going = re.compile(
            rf"\b{_ASKED}(?P<thing>{_THING})\s+(?:{_GOING}){_ON_ITS_WAY}{means}"
            r"(?P<rest>[^.!?;]*)",
            re.IGNORECASE,
        )
        for pattern, lead in ((sent, ""), (going, "could you ")):
            found = pattern.search(text)
            if found is None:
                continue
            thing = found.group("thing")
            if thing.lower() not in ("it", "them") and not _takes(terms, op, thing):
                continue
            verb = _verb(op)
            rest = re.sub(r"^(\s*)for\b", r"\1to", found.group("rest"), flags=re.IGNORECASE)
            read = f"{lead}{verb} {thing}{rest}"
            evidence = Evidence(words=found.group(0).strip(), meaning=read.strip())
            return text[: found.start()] + read + text[found.end() :], [evidence]
    return text, []


def _takes(terms: Terms, op: Operation, thing: str) -> bool:
    """Whether ``thing`` names an item the service sends: a thing it does not take is left
    to the request as said, never read as another service's ("send my form via the courier
    desk" where only the fax takes forms)."""
    items = [m for m in terms.lex.scan(terms.lex.tokens(thing)) if m.kind == "item"]
    return bool(items) and (op.input is None or any(op.input in m.ids for m in items))


def _means_phrases(office: Office) -> list[tuple[str, Operation]]:
    """The words that name each send-out facility or its one service's means ("courier
    desk", "post bag", "courier"), longest first, each with that service."""
    out: list[tuple[str, Operation]] = []
    for op in office.operations:
        # a service whose name says what it sends in ("send in the ship's bag") names itself
        # by that, wherever it is done, also at a desk that runs other services
        if op.sends_out and (container := _container(op.name)):
            out.append((container, op))
    for facility in office.facilities:
        ops = [office.operation(o) for o in facility.operations]
        # a facility that also works on things here ("can my tunic go through the hot
        # press": pressed) names no send-out by itself: read as before
        if len(ops) != 1 or not ops[0].sends_out:
            continue
        op = ops[0]
        # and its verbs that name a sender ("ship back" whose verbs say "courier": "can it
        # go out with the courier?")
        senders = [v for v in op.verbs if " " not in v and language.is_noun(v)]
        for name in (facility.name, *facility.synonyms, *means_words(op.name), *senders):
            out.append((language.fold(name), op))
    return sorted(out, key=lambda p: -len(p[0]))


_CONTAINER_OPENERS = frozenset({"in", "into", "inside"})
_ARTICLES = frozenset({"the", "a", "an", "our"})


def _container(name: str) -> str | None:
    """What a send-out service's name says it sends things in: "send in the ship's bag":
    "ship's bag" (two words at least, so "send in" alone names nothing)."""
    words = language.fold(name).split()
    for k, w in enumerate(words):
        if w in _CONTAINER_OPENERS:
            rest = [x for x in words[k + 1 :] if x not in _ARTICLES]
            return " ".join(rest) if len(rest) >= 2 else None
    return None


def _verb(op: Operation) -> str:
    """The service's verb to ask for it with ("courier", "post"); its name's means where its
    verbs say something else ("dispatch" for "send by courier" reads as "courier" too)."""
    means = means_words(op.name)
    return means[0] if means else op.verbs[0]
