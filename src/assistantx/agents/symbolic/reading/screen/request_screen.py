"""The request screen: the message cut into pieces, each judged by the table of rules
(``rules``), and what the pieces make of the whole: a decline, the replies to a message with
no request, a "Shall I ...?", or the request left for the later stages, rewritten so they can
read it (``rewrites``)."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.lexicon import Lexicon
from assistantx.agents.symbolic.reading.screen.answer import answered, aside
from assistantx.agents.symbolic.reading.screen.correction import corrected
from assistantx.agents.symbolic.reading.screen.english import split_words
from assistantx.agents.symbolic.reading.screen.findings import DROPPED, Finding, Screened
from assistantx.agents.symbolic.reading.screen.pieces import Message, pieces, without
from assistantx.agents.symbolic.reading.screen.rewrites import rewrite
from assistantx.agents.symbolic.reading.screen.rules import RULES
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.speech import content
from assistantx.agents.symbolic.reading.speech_acts import acts_reader
from assistantx.core.office import Office
from assistantx.core.task_schema import Evidence


class RequestScreen:
    """Screens requests against one office (its people, items, facilities and purposes)."""

    def __init__(self, office: Office, lex: Lexicon) -> None:
        self.office = office
        self.lex = lex
        self.terms = Terms(office, lex)

    def screen(self, text: str, requester: str) -> Screened:
        terms = self.terms
        text, fixes = corrected(terms, text)
        acts = acts_reader(terms.acts, terms.self_words, split_words(text))
        msg = Message(text=text, pieces=pieces(text, terms.lex.read, acts))
        findings: list[Finding] = []
        for piece in msg.pieces:
            for _, rule in RULES:
                found = rule(terms, msg, piece, requester)
                if found is not None:
                    findings.append(found)
                    break
        out = Screened(text=text)
        out.evidence = [
            *fixes,
            *(Evidence(words=f.piece.text, meaning=f.meaning) for f in findings),
        ]
        out.hints = [f.hint for f in findings if f.hint is not None]
        withdrawn = [f for f in findings if f.verdict == "withdrawn"]
        cut = withdrawn[-1].piece.end if withdrawn else 0
        live = [f for f in findings if f.piece.start >= cut]
        declines = [f for f in live if f.verdict in ("destructive", "unsupported")]
        if declines:
            out.decline, out.outcome = declines[0].message, "unachievable"
            return out
        dropped = [f.piece for f in findings if f.verdict in DROPPED]
        left = without(text, cut, dropped)
        meant = set(content(split_words(left))) - terms.en.courtesy  # "hi," left of a statement
        kept = [p for p in msg.pieces if p.start >= cut and not any(p is d for d in dropped)]
        if not meant or aside(terms, left, live, kept):
            negated = [f for f in live if f.verdict == "negated"]
            if negated:
                said = "; ".join(repr(f.piece.text) for f in negated)
                out.decline = (
                    f"OK, I won't do that (you wrote {said}). I did nothing; "
                    "tell me if you do need something."
                )
                out.outcome = "done"
                return out
            if live or withdrawn:
                return answered(out, live, withdrawn=bool(withdrawn))
        if any(p.acts.need for p in kept) and not any(p.acts.request for p in kept):
            out.confirm = True  # "Min needs scissors.": restate and ask before moving
        context = [c for f in live if f.verdict in ("statement", "condition") for c in f.context]
        left, rewrites = rewrite(terms, msg, left, out.hints, context)
        out.evidence += rewrites
        out.text = left
        return out

    def unknown_thing(self, words: list[str]) -> str:
        """ "a tape measure" in "who has a tape measure" (``Terms.unknown_thing``)."""
        return self.terms.unknown_thing(words)

    def capabilities(self) -> str:
        """What this office lets the assistant do, in words (``Terms.capabilities``)."""
        return self.terms.capabilities()
