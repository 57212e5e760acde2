"""The request screen in three steps: the message cut into pieces, each judged by the table of
rules (``verdicts``); the request left for the later stages, rewritten so they can read it
(``request``, ``rewrites``); and, once those stages have read it, what the pieces make of the
whole (``decide``): a decline, the replies to a message with no request, a "Shall I ...?",
or the request."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.lexicon import Lexicon
from assistantx.agents.symbolic.reading.screen.actually_instead import actually_instead
from assistantx.agents.symbolic.reading.screen.address_part import outside_address_part
from assistantx.agents.symbolic.reading.screen.addressed import only_addressed
from assistantx.agents.symbolic.reading.screen.answer import answered, aside
from assistantx.agents.symbolic.reading.screen.anyones import anyones
from assistantx.agents.symbolic.reading.screen.asked_leave import asked_leave
from assistantx.agents.symbolic.reading.screen.brought_back import brought_back
from assistantx.agents.symbolic.reading.screen.contracted_is import contracted_is
from assistantx.agents.symbolic.reading.screen.contractions import contractions_apart
from assistantx.agents.symbolic.reading.screen.correction import REPLACED, corrected
from assistantx.agents.symbolic.reading.screen.dropped_subject import subject_restored
from assistantx.agents.symbolic.reading.screen.english import split_words
from assistantx.agents.symbolic.reading.screen.facility_means import facility_means
from assistantx.agents.symbolic.reading.screen.findings import Finding, Request, Screened, Spoken
from assistantx.agents.symbolic.reading.screen.head_noun_back import head_noun_back
from assistantx.agents.symbolic.reading.screen.hedges import without_hedges
from assistantx.agents.symbolic.reading.screen.how_taken import how_taken
from assistantx.agents.symbolic.reading.screen.later_service import without_later_service
from assistantx.agents.symbolic.reading.screen.opened_machine import opened_to_take
from assistantx.agents.symbolic.reading.screen.others_future_need import others_future_need
from assistantx.agents.symbolic.reading.screen.owned_clipped import owned_clipped
from assistantx.agents.symbolic.reading.screen.owned_head import owned_head
from assistantx.agents.symbolic.reading.screen.participle_clause import own_participle
from assistantx.agents.symbolic.reading.screen.person_is import person_is
from assistantx.agents.symbolic.reading.screen.pieces import Message, pieces
from assistantx.agents.symbolic.reading.screen.pronoun_subject import named_subject
from assistantx.agents.symbolic.reading.screen.rejection import rejected_alternative
from assistantx.agents.symbolic.reading.screen.rewrites import rewrite
from assistantx.agents.symbolic.reading.screen.rules import RULES
from assistantx.agents.symbolic.reading.screen.same_work_added import same_work_added
from assistantx.agents.symbolic.reading.screen.self_introduction import self_introduction
from assistantx.agents.symbolic.reading.screen.statement import owner_work_asked, sent_by_means
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.screen.timing import without_time_idioms
from assistantx.agents.symbolic.reading.screen.unasked import unasked
from assistantx.agents.symbolic.reading.screen.undone_work import undone_work
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
        """The whole screen at once: the pieces' verdicts, the request left, the decision."""
        spoken = self.verdicts(text, requester)
        return self.decide(spoken, self.request(spoken))

    def verdicts(self, text: str, requester: str) -> Spoken:
        """The message corrected, cut into pieces (each lexed and its speech acts read), and
        each piece judged by the table of rules (the first that matches decides it)."""
        terms = self.terms
        text, intro = self_introduction(terms.office, requester, text)  # "Bren here, ..."
        text, idioms = without_time_idioms(terms, text)  # "when you get a sec": no thing
        text, after = without_later_service(terms, text)  # "before it goes on the ESDA"
        text, opened = opened_to_take(terms, text)  # "open the microwave and take my lunch out"
        text, later = others_future_need(terms, text)  # "Mark's going to need": Mark needs
        text, person = person_is(terms, text, requester)  # "Gao's busy and needs ...": is
        text, subject = named_subject(terms, text, requester)  # "Rose is wet, she needs ..."
        text, heads = head_noun_back(terms, text)  # "got sticky tape? bring a dispenser"
        text, owned = owned_head(terms, text, requester)  # "my lamp": my inspection lamp
        text, clipped = owned_clipped(terms, text, requester)  # "my batt": my camera battery
        text, back = brought_back(terms, text)  # "and a coffee on the way back": mine
        # "she'll frank it": "she 'll", never the word "shell" (before any word is looked up)
        text, apart = contractions_apart(text)
        # "been at the machine": I've been
        text, restored = subject_restored(text, frozenset(terms.lex.items))
        text, doing = own_participle(text, terms.lex.read)  # "?, doing a survey on ...": I'm
        # "UV bulb's gone": the bulb is gone; "my laptop's flat": the laptop is
        text, stated = contracted_is(text, terms.lex.item_heads)
        text, taken = how_taken(terms, text)  # "a brew, milk no sugar": no milk to fetch
        text, leave = asked_leave(text)  # "can I nick Robin's mute?": asks to borrow it
        text, hedged = without_hedges(text)  # "Holly, I think, has one": Holly has one
        text, rejected = rejected_alternative(terms, text)  # "not a ruler, a tape measure"
        text, added = same_work_added(terms, text)  # "... also print it for Sam": twice
        text, actually = actually_instead(terms, text)  # ". actually, print it for Sam"
        text, fixes = corrected(terms, text)
        text, sent = sent_by_means(terms, text)  # "this form needs to go by courier to ..."
        text, means = facility_means(terms, text)  # "send my form via the courier desk to ..."
        text, undone = undone_work(terms, text)  # "Hal still hasn't signed it. Can you ..."
        fixes = [
            *intro,
            *idioms,
            *after,
            *opened,
            *later,
            *person,
            *subject,
            *heads,
            *owned,
            *clipped,
            *back,
            *apart,
            *restored,
            *doing,
            *stated,
            *taken,
            *leave,
            *hedged,
            *rejected,
            *added,
            *actually,
            *fixes,
            *sent,
            *means,
            *undone,
        ]
        acts = acts_reader(terms.acts, terms.self_words, split_words(text))
        msg = Message(
            text=text,
            pieces=pieces(text, terms.lex.read, acts),
            lexed=terms.lex.read(text),
            replaced=any(e.meaning.startswith(REPLACED) for e in fixes),
        )
        findings: list[Finding] = []
        for piece in msg.pieces:
            if outside_address_part(terms, msg, piece):
                continue  # "..., Water Gardens, Harlow": the destination's, no rule reads it
            for _, rule in RULES:
                found = rule(terms, msg, piece, requester)
                if found is not None:
                    findings.append(found)
                    break
        return Spoken(msg=msg, findings=findings, fixes=fixes)

    def request(self, spoken: Spoken) -> Request:
        """What is left of the message once the pieces that ask nothing are taken out,
        rewritten so the later stages can read it (``rewrites``)."""
        context = [
            c
            for f in spoken.live
            if f.verdict in ("statement", "condition", "thanks")
            for c in f.context
        ]
        left, anyone = anyones(spoken.left)  # "can someone lend me theirs": one, anyone's
        text, rewrites = rewrite(self.terms, spoken.msg, left, spoken.hints, context)
        return Request(text=text, evidence=[*anyone, *rewrites])

    def decide(self, spoken: Spoken, request: Request) -> Screened:
        """What the pieces make of the whole message: a decline, the replies to a message
        with no request, a "Shall I ...?" to ask first, or the request left to act on."""
        terms = self.terms
        out = Screened(text=spoken.msg.text)
        out.evidence = [
            *spoken.fixes,
            *(Evidence(words=f.piece.text, meaning=f.meaning) for f in spoken.findings),
        ]
        out.hints = spoken.hints
        live, withdrawn, kept = spoken.live, spoken.withdrawn, spoken.kept
        declines = [f for f in live if f.verdict in ("destructive", "unsupported")]
        if declines:
            out.decline, out.outcome = declines[0].message, "unachievable"
            return out
        instead = [f for f in live if f.verdict == "instead"]
        # what the office cannot do as asked, with what it can do instead ("Shall I bring it
        # to you instead?"): asked, and on a yes the offer is read as the request
        if instead:
            out.question, out.offer = instead[0].message, instead[0].offer
            return out
        unplaced = [f for f in live if f.verdict in ("unplaced", "which")]
        # a thing told to go where nothing of the office is, or one of several things kept
        # for its owner: asked, never moved
        if unplaced:
            out.question = unplaced[0].message
            return out
        left = spoken.left
        meant = set(content(split_words(left))) - terms.en.courtesy  # "hi," left of a statement
        aside_left = aside(terms, left, live, kept, withdrawn=bool(withdrawn))
        if not meant or aside_left or only_addressed(spoken):
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
        needs = [p for p in kept if p.acts.need]
        if needs and not any(p.acts.request for p in kept):
            # "Min needs scissors.": restate and ask before moving; not "Robin needs to sign
            # my report.", its owner's request for the signature
            out.confirm = not all(owner_work_asked(spoken.msg, p) for p in needs)
        if unasked(terms, kept):
            # nothing asked, and no request said short: told, so restate it and ask first
            out.confirm = True
        out.evidence += request.evidence
        out.text = request.text
        return out

    def unknown_thing(self, words: list[str]) -> str:
        """ "a tape measure" in "who has a tape measure" (``Terms.unknown_thing``)."""
        return self.terms.unknown_thing(words)

    def capabilities(self) -> str:
        """What this office lets the assistant do, in words (``Terms.capabilities``)."""
        return self.terms.capabilities()
