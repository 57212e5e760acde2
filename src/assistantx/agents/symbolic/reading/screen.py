"""The request screen: ask or decline, never guess — before any task is read from a request.

A request is cut into pieces (sentences, and the comma/"and"/"then" parts of one); a table of
rules, tried in priority order, says what each piece is. The first rule that matches a piece
decides it:

==============  ==================================================================  ==========
rule            matches                                                             effect
==============  ==================================================================  ==========
withdrawn       "never mind", "forget it", "forget about the scissors"              drops all
                                                                                    said before
exclusion       "not from Wang though", "not Chen's"                                a hint that
                                                                                    keeps them out
wish            "keep everyone away from Mao's seal", "nobody take my mug"          words only
thanks          "thanks for the pen!", "say thanks to Wang for the pen"             words only
negated         "don't bring me ...", "no need to print ..."                        drops piece
destructive     "throw away Wang's stapler", "hide ...", "get rid of ..."           declines
fact            "Wang is away", "Zhang is in the meeting room",                     a hint;
                "Zhang's stapler is broken"                                         drops piece
question        "who has a tape measure?", "is the printer working?" (not "could    answered;
                you bring me ...?", a request)                                      "Shall I?"
statement       "my laptop cable is too short", "I spilled my tea"                  context
unsupported     a service the office does not offer ("scan my contract",            declines
                "make me a cup of tea")
==============  ==================================================================  ==========

The speech acts (wish, thanks, question, statement) are ``speech``'s: only a request moves the
robot, the others are answered in words. A message with no request left is answered with the
replies of its pieces; an information question that may be a request in disguise ("does anyone
have a stapler?") is answered and met with "Shall I bring you one?"; a third person's need
with no request wording ("Min needs scissors") is restated and asked before anything moves.

Then two rewrites make the rest readable by the frame parser: a thing named by its purpose
("something to cut this with") becomes the office's item type declared for that purpose, and
"another one" after a stated condition ("Zhang's stapler is broken") becomes that item.

The English words live in the package's ``data/english.yaml`` (``assistantx.core.english``); the
office's words (people, items, facilities, purposes) come from the office file. Pieces are
removed from the original text by their character spans, never re-joined, so what is left
parses as the person wrote it.
"""

from __future__ import annotations

import functools
import re
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Literal

from assistantx.agents.symbolic.reading._objects import modifiers
from assistantx.agents.symbolic.reading.lexicon import Lexicon, Mention
from assistantx.agents.symbolic.reading.speech import NEED_PHRASES, SpeechActs, content
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import language
from assistantx.core.english import entries_of
from assistantx.core.english import words as english_words
from assistantx.core.office import Office
from assistantx.core.task_schema import DeclineOutcome, Evidence, Hint
from assistantx.memory.names import normalize

_WORD = re.compile(r"[A-Za-z0-9]+(?:['’][A-Za-z]+)?")
# A spaced dash joins two sentences as a full stop would ("I'm on the ward - print my rota").
_SENTENCE_END = re.compile(r"[.!?;\n]+|\s[-–—]+\s")
# "sorry, I meant ...", "no wait, ...", "..., no, a pen", "I mean ...": the words after it correct
# what was just said (only when they name one person or item, ``_corrected``)
_CORRECTION = re.compile(
    r"(?:[,;.!?]|\s[-–—]+)\s*"
    r"(?:(?:sorry|oops|no wait|wait no|oh wait|no sorry|sorry no|no(?=[,!.]))\b"
    r"[,!.]?\s*(?:i\s+mean[t]?\b)?|i\s+mean[t]?\b)[,:]?\s*",
    re.IGNORECASE,
)
# "bring me the… actually, just print it": after a trailing-off, "actually" corrects too.
_ELLIPSIS_ACTUALLY = re.compile(r"(?:\.{2,}|…)\s*actually\b[,:]?\s*(?:no\b[,.!]?\s*)?", re.I)
# The words before a correction's own request verb ("just", "please", "rather").
_CORRECTION_FILLERS = frozenset(
    {"just", "please", "rather", "instead", "simply", "only", "can", "you", "could"}
)
# "a new one", "another", "a replacement": a need that replaces an item said to be failing.
_REPLACEMENT = english_words("replacement_words")
_CONDITION_WORDS = english_words("condition_openers")
_PIECE_BREAK = re.compile(r",|\s+(?:and|then|but)\s+", re.IGNORECASE)
_DETERMINERS = english_words("screen_determiners")


@dataclass(frozen=True)
class English:
    """The word lists of ``english.yaml``, phrases as tuples of words."""

    lead_in: frozenset[str]
    withdraw: tuple[tuple[str, ...], ...]
    negators: tuple[tuple[str, ...], ...]
    negation_fillers: frozenset[str]
    destructive: tuple[tuple[str, ...], ...]
    copulas: tuple[tuple[str, ...], ...]
    away: tuple[tuple[str, ...], ...]
    here: tuple[tuple[str, ...], ...]
    location_prepositions: frozenset[str]
    conditions: tuple[tuple[str, ...], ...]
    fact_openers: frozenset[str]
    another_one: tuple[str, ...]
    purpose_heads: tuple[str, ...]
    purpose_links: tuple[str, ...]
    purpose_tail: frozenset[str]
    service_verbs: frozenset[str]
    service_products: frozenset[str]
    modifier_prepositions: frozenset[str]
    courtesy: frozenset[str]
    own_item_lost: tuple[tuple[str, ...], ...]
    exclusion_openers: frozenset[str]
    elliptical_withdrawals: tuple[tuple[str, ...], ...]


@functools.cache
def english() -> English:
    raw = entries_of()

    def phrases(key: str) -> tuple[tuple[str, ...], ...]:
        # longest first, so "throw away" wins over "throw"
        found = {tuple(_words(str(p))) for p in raw[key]}
        return tuple(sorted(found, key=lambda p: (-len(p), p)))

    def words(key: str) -> frozenset[str]:
        return frozenset(w for p in raw[key] for w in _words(str(p)))

    return English(
        lead_in=words("lead_in"),
        withdraw=phrases("withdraw"),
        negators=phrases("negators"),
        negation_fillers=words("negation_fillers"),
        destructive=phrases("destructive"),
        copulas=phrases("copulas"),
        away=phrases("away"),
        here=phrases("here"),
        location_prepositions=words("location_prepositions"),
        conditions=phrases("conditions"),
        fact_openers=words("fact_openers"),
        another_one=tuple(sorted((str(p) for p in raw["another_one"]), key=lambda p: -len(p))),
        purpose_heads=tuple(str(p) for p in raw["purpose_heads"]),
        purpose_links=tuple(str(p) for p in raw["purpose_links"]),
        purpose_tail=words("purpose_tail"),
        service_verbs=words("service_verbs"),
        service_products=words("service_products"),
        modifier_prepositions=words("modifier_prepositions"),
        courtesy=words("courtesy"),
        own_item_lost=phrases("own_item_lost"),
        exclusion_openers=words("exclusion_openers"),
        elliptical_withdrawals=phrases("elliptical_withdrawals"),
    )


def _words(text: str) -> list[str]:
    return language.words(text)


def _starts_with(words: list[str], at: int, phrase: tuple[str, ...]) -> bool:
    return tuple(words[at : at + len(phrase)]) == phrase


def _find(words: list[str], phrases: tuple[tuple[str, ...], ...]) -> tuple[int, tuple[str, ...]]:
    for at in range(len(words)):
        for p in phrases:
            if _starts_with(words, at, p):
                return at, p
    return -1, ()


@dataclass(frozen=True)
class Piece:
    """A part of the request: its text, its place in the original and its words."""

    text: str
    start: int
    end: int
    words: list[str]
    asks: bool = False  # the sentence ends with a question mark

    def verb_at(self, lead_in: frozenset[str]) -> int:
        """Index of the request's verb: the first word that is no lead-in ("could you ...")."""
        return next((n for n, w in enumerate(self.words) if w not in lead_in), len(self.words))


Verdict = Literal[
    "withdrawn",
    "note",
    "condition",
    "exclusion",
    "wish",
    "thanks",
    "negated",
    "destructive",
    "fact",
    "question",
    "statement",
    "unsupported",
]


@dataclass(frozen=True)
class Finding:
    verdict: Verdict
    piece: Piece
    meaning: str  # in words, for the evidence
    hint: Hint | None = None
    message: str = ""  # for a decline, or the reply to a non-request
    offer: str = ""  # the request a "Shall I ...?" would carry out on a yes
    shall: str = ""  # the "Shall I ...?" question itself
    context: tuple[str, ...] = ()  # item types and people a statement named


@dataclass
class Screened:
    """What the screen made of a request."""

    text: str  # what is left for the frame parser
    decline: str | None = None
    outcome: DeclineOutcome = "unachievable"
    hints: list[Hint] = field(default_factory=list)
    evidence: list[Evidence] = field(default_factory=list)
    question: str | None = None  # "... Shall I bring you one?": asked before anything moves
    offer: str | None = None  # the request carried out when the answer is yes
    confirm: bool = False  # a third person's need only: restate the reading and ask


Rule = Callable[["RequestScreen", Piece, str], "Finding | None"]


class RequestScreen:
    """Screens requests against one office (its people, items, facilities and purposes)."""

    def __init__(self, office: Office, lex: Lexicon) -> None:
        self.office = office
        self.lex = lex
        self.en = english()
        self.acts = SpeechActs(lex)
        self._office_words = frozenset(
            w
            for phrase in (
                *lex.items,
                *lex.facilities,
                *lex.people,
                *lex.name_words,
                *(o.name for o in office.operations),
                *lex.cue_words,
            )
            for w in _words(phrase)
        )

    # -- the table -----------------------------------------------------------------------
    RULES: tuple[tuple[Verdict, Rule], ...] = ()  # filled in below the class

    def screen(self, text: str, requester: str) -> Screened:
        text, corrected = self._corrected(text)
        self._text = text
        self._noting: int | None = None  # where a note began ("note this down: ...")
        self._withdrawing = False  # a withdrawal was read: what follows may be its reason
        self._negating = False  # a negated errand was read: what follows may be its reason
        pieces = _pieces(text)
        self._pieces = pieces
        findings: list[Finding] = []
        for piece in pieces:
            for _, rule in self.RULES:
                found = rule(self, piece, requester)
                if found is not None:
                    findings.append(found)
                    break
        out = Screened(text=text)
        out.evidence = [
            *corrected,
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
        dropped = [f.piece for f in findings if f.verdict in _DROPPED]
        left = _without(text, cut, dropped)
        meant = set(content(_words(left))) - self.en.courtesy  # "hi," left of a statement
        kept = [p for p in pieces if p.start >= cut and not any(p is d for d in dropped)]
        if not meant or self._aside(left, live, kept):
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
                return self._answered(out, live, withdrawn=bool(withdrawn))
        if any(self.acts.need(p.words, self._self_words) for p in kept) and not any(
            self.acts.request(p.words) for p in kept
        ):
            out.confirm = True  # "Min needs scissors.": restate and ask before moving
        context = [c for f in live if f.verdict in ("statement", "condition") for c in f.context]
        left, rewrites = self._rewrite(left, out.hints, context)
        out.evidence += rewrites
        out.text = left
        return out

    def _corrected(self, text: str) -> tuple[str, list[Evidence]]:
        """ "bring me Rich's clipboard - sorry, I meant Dawn's", "..., no wait, Dawn's": a
        correction of one person or item right after it is said replaces it; the retracted
        one is never acted on (nor is the whole message dropped as withdrawn)."""
        match = _CORRECTION.search(text) or _ELLIPSIS_ACTUALLY.search(text)
        if match is None:
            return text, []
        before, after = text[: match.start()], text[match.end() :]
        fix = re.split(r"[.!?;\n]", after, maxsplit=1)[0]
        rest = after[len(fix) :]
        tokens = self.lex.tokens(fix)
        if self._opens_request(tokens):
            # "fetch Bill's tripod... actually, no, just print my draft": a correction that
            # says a request of its own withdraws the request it breaks off; the withdrawn
            # verb never runs (what came before that request's sentence stays)
            kept = _SENTENCE_END.split(before.rstrip(" .…,;-–—"))
            cut = before.rstrip(" .…,;-–—").rfind(kept[-1]) if kept[-1] else len(before)
            dropped = before[cut:].strip()
            fixed = before[:cut] + after
            meaning = f"withdraws {dropped!r}, asks instead"
            return fixed, [Evidence(words=text[match.start() :].strip(), meaning=meaning)]
        # "..., sorry, his laser, not the ruler": what is rejected after it says which one
        # the correction replaces; the correction itself is the part before "not"
        cut = next((k for k, t in enumerate(tokens) if t.word == "not" and k), len(tokens))
        tokens, rejected = tokens[:cut], tokens[cut:]
        if not tokens or len(tokens) > 5:
            return text, []
        mentions = [m for m in self.lex.scan(tokens) if m.kind in ("person", "item")]
        if len(mentions) != 1 or len(mentions[0].ids) != 1:
            return text, []
        new = mentions[0]
        names = self._spellings(new.kind, before)
        if rejected:
            said_no = " ".join(t.text for t in rejected)
            names = (self._spellings(new.kind, said_no) & names) or names
        if not names:
            return text, []
        pattern = "|".join(re.escape(n) for n in sorted(names, key=len, reverse=True))
        spots = list(re.finditer(rf"\b(?:{pattern})\b", before, re.IGNORECASE))
        if not spots:
            return text, []
        old = spots[-1]
        said = new.text.replace("’", "'").removesuffix("'s")
        if new.kind == "item":
            said = self.office.item_type(new.ids[0]).name
        fixed = before[: old.start()] + said + before[old.end() :] + rest
        return fixed, [Evidence(words=text[match.start() :].strip(), meaning=f"means {said}")]

    def _opens_request(self, tokens: Sequence[Token]) -> bool:
        """Whether a correction's words open with a request verb of their own ("just print
        my draft", "please bind my plan instead"), not a person or an item alone."""
        words = [t.word for t in tokens if t.word not in _CORRECTION_FILLERS]
        return (
            bool(words)
            and (words[0] in self.lex.cue_words or words[0] in self.lex.operation_words)
            and self.acts.request(words)
        )

    def _spellings(self, kind: str, text: str) -> set[str]:
        """How the people (or items) ``text`` names are written there."""
        tokens = self.lex.tokens(text)
        ids = {i for m in self.lex.scan(tokens) if m.kind == kind for i in m.ids}
        if kind == "person":
            people = [self.office.person(i) for i in ids]
            return {n for p in people for n in (p.name, *p.aliases, *p.name.split()) if n}
        return {
            n
            for i in ids
            for t in [self.office.item_type(i)]
            for n in (t.name, *t.synonyms, language.plural(t.name))
        }

    def _aside(self, left: str, live: list[Finding], kept: list[Piece]) -> bool:
        """What is left beside a thanks, wish or withdrawal, or after a note, condition or
        report, names nothing of this office and asks for nothing ("..., lifesaver", "...,
        all sorted"): an aside, not a request. Before a report it is no closing remark
        ("hello there. I don't know more than I wrote" still says nothing of what is needed)."""
        anywhere = any(f.verdict in ("thanks", "wish", "withdrawn") for f in live)
        reports = [f.piece.start for f in live if f.verdict in _SAYS_NOTHING_TO_DO]
        closing = bool(reports) and all(p.start > min(reports) for p in kept)
        if not (anywhere or closing):
            return False
        words = _words(left)
        if set(words) & self._office_words or self.acts.request(words):
            return False
        # "something longer?", "another one": what a statement beside it makes a request of
        helpers = {w for p in (*self.en.purpose_heads, *self.en.another_one) for w in _words(p)}
        return not set(words) & helpers

    def _answered(self, out: Screened, live: list[Finding], *, withdrawn: bool) -> Screened:
        """No request left: the replies to what was said, or one "Shall I ...?"."""
        out.outcome = "done"
        offers = [f for f in live if f.offer]
        if len(offers) == 1 and not any(f.verdict in ("wish", "thanks") for f in live):
            out.question = f"{offers[0].message} {offers[0].shall}"
            out.offer = offers[0].offer
            return out
        replies = [f.message for f in live if f.message]
        if any(r.startswith("Noted. ") for r in replies):  # one "Noted", then what to do
            replies = [_unnoted(r) for r in replies]
            replies.sort(key=lambda r: not r.startswith("Noted. "))
        if withdrawn:
            replies.insert(0, "OK, I've dropped that request.")
        facts = [f.meaning.removeprefix("a fact: ") for f in live if f.verdict == "fact"]
        if facts:
            replies.append(f"Thanks, noted: {'; '.join(facts)}.")
        if not replies:
            replies = ["Noted."]
        out.decline = " ".join(dict.fromkeys(replies)) + " I did nothing."
        return out

    # -- rules ---------------------------------------------------------------------------
    def _withdrawn(self, piece: Piece, requester: str) -> Finding | None:
        found = self._withdrawal(piece)
        if found is not None:
            self._withdrawing = True
            return found
        told = any(language.is_finite_verb(w) for w in piece.words)
        if (
            self._withdrawing
            and told
            and not any(self.acts.request(p.words) for p in self._pieces if p.start >= piece.start)
        ):
            # "never mind, found the stapler in my drawer, thanks": the reason for it, told as
            # what happened, not an errand; a request after it ("..., bring me a pen instead")
            # is read, and so is a bare correction ("no wait, a pencil": asked about)
            return Finding("withdrawn", piece, "the reason the request is withdrawn")
        return None

    def _withdrawal(self, piece: Piece) -> Finding | None:
        words = [w for w in piece.words if w not in ("actually", "oh", "ok", "okay", "please")]
        if tuple(words) in self.en.withdraw or self.acts.withdrawal(words):
            return Finding("withdrawn", piece, "withdraws the request")
        said = tuple(w for w in piece.words if w not in ("oh", "ok", "okay", "wait", "hmm"))
        if piece.start > 0 and said in self.en.elliptical_withdrawals:
            return Finding("withdrawn", piece, "withdraws what was asked before")
        if piece.start > 0 and not piece.asks and self.acts.had_already(piece.words):
            return Finding("withdrawn", piece, "what was asked for is had already")
        return None

    def _note(self, piece: Piece, requester: str) -> Finding | None:
        """ "note this down: the tape ran out", "mark this down: ...": a note to keep, answered
        in words; a later piece of the same message is part of it unless it asks for
        something ("Note this down. Ida is away next week.")."""
        said = self.acts.note(piece.words)
        noting = self._noting is not None and piece.start >= self._noting
        if said is None and not (noting and not self.acts.request(piece.words)):
            return None
        if said is not None:
            self._noting = piece.start
            if said and self.acts.request(said):
                return None  # "please note I need a ruler": a request, read as one
        return Finding("note", piece, "a note to keep, not a request", message="Noted.")

    def _condition(self, piece: Piece, requester: str) -> Finding | None:
        """ "if Hal ever needs a ruler, Ida has one": a condition says when, never what to do;
        with no request beside it the message is information, answered in words."""
        deferred = self.acts.defers(_words(self._text))
        put_off = self.acts.defers(piece.words) and not self.acts.imperative(piece.words)
        if not put_off and self.acts.future_need(piece.words, deferred):
            offered = self._replacement_offer(piece)
            if offered is not None:
                return offered
        if put_off or self.acts.future_need(piece.words, deferred):
            return Finding(
                "condition",
                piece,
                "a need that may come later, not a request for now",
                message="Noted. Tell me when you need it and I'll bring it then.",
            )
        if not self.acts.condition(piece.words, piece.asks):
            return None
        # what the condition names is context for a request beside it, as a statement's is:
        # "if Hedda isn't using her laser, could you bring it over?" asks for Hedda's laser
        named = tuple(self._stated_items(piece, requester)) + tuple(
            f"person:{p}" for p in self._named(piece.text, "person")[:1]
        )
        return Finding(
            "condition",
            piece,
            "a condition, not a request",
            message="Noted; I'll keep it in mind.",
            context=named,
        )

    def _replacement_offer(self, piece: Piece) -> Finding | None:
        """ "my tripod is wobbly, I might need a new one": a possible need of a replacement
        for an item said to be failing, with no condition and no "later", is offered ("Shall
        I bring you a tripod?"), never fetched at once nor only noted."""
        words = set(piece.words)
        if not words & _REPLACEMENT or words & _CONDITION_WORDS or self.acts.later(piece.words):
            return None
        said = (
            self._named(piece.text, "item") or self._named(self._text[: piece.start], "item")[-1:]
        )
        if len(said) != 1:
            return None
        t = self.office.item_type(said[0])
        if t.kind not in ("belonging", "product"):
            return None
        verb = "get" if t.kind == "product" else "bring"
        thing = f"{_article(t.name)} {t.name}"
        return Finding(
            "condition",
            piece,
            f"a possible need of a new {t.name}: offered, not fetched",
            message=f"Sorry about your {t.name}.",
            offer=f"{verb} me {thing}",
            shall=f"Shall I {verb} you {thing}?",
        )

    def _exclusion(self, piece: Piece, requester: str) -> Finding | None:
        """ "not from Wang though", "Not Chen's, they're blunt": that person's item is not
        wanted; a hint that keeps them out, never a party."""
        words = [w for w in piece.words if w not in ("but", "though", "just", "please")]
        if not words or words[0] not in self.en.exclusion_openers:
            return None
        people = self._named(piece.text, "person")
        items = self._named(piece.text, "item") or self._named(self._text, "item")
        if len(people) != 1 or not items:
            return None
        who = self.office.person(people[0]).name
        thing = self.office.item_type(items[0]).name
        hint = Hint(
            kind="condition",
            person=people[0],
            value="not wanted",
            item_type=items[0],
            said=piece.text,
        )
        return Finding("exclusion", piece, f"not {who}'s {thing}", hint)

    def _wish(self, piece: Piece, requester: str) -> Finding | None:
        if self.acts.world_wish(piece.words):
            return Finding(
                "wish",
                piece,
                "a wish about the place, not a request",
                message="Noted; that is not something I can change.",
            )
        if not self.acts.wish(piece.words):
            return None
        things = self._named(piece.text, "item")
        what = f"the {self.office.item_type(things[0]).name}" if len(things) == 1 else "anything"
        return Finding(
            "wish",
            piece,
            "a wish about other people, not a request",
            message=(
                f"Understood: I won't move or hand out {what} unless its owner asks me to. "
                "I can't keep people away from things, though."
            ),
        )

    def _thanks(self, piece: Piece, requester: str) -> Finding | None:
        act = self.acts.thanks(piece.words)
        if act is None:
            return None
        if act.relay:
            people = self._named(piece.text, "person")
            who = self.office.person(people[0]).name if len(people) == 1 else "them"
            message = (
                f"I only pass on messages as part of an errand, so please tell {who} yourself."
            )
            return Finding("thanks", piece, "thanks to pass on, not a request", message=message)
        return Finding("thanks", piece, "thanks, not a request", message="You're welcome!")

    def _question(self, piece: Piece, requester: str) -> Finding | None:
        kind = self.acts.question(piece.words, piece.asks)
        if kind != "info":
            return None
        items = self._named(piece.text, "item")
        facilities = self._named(piece.text, "facility")
        people = self._named(piece.text, "person")
        if len(items) == 1 and not facilities:
            found = self._item_question(piece, items[0], requester)
            if self.acts.doubts_ability(piece.words) and found.offer:
                # "can you even carry ...?": yes, said first; the errand only on a yes
                message = f"Yes, I can do that. {found.message}"
                return Finding(
                    found.verdict,
                    piece,
                    found.meaning,
                    message=message,
                    offer=found.offer,
                    shall=found.shall,
                )
            return found
        if facilities:
            f = self.office.facility(facilities[0])
            where = self.office.location(f.location).name
            message = (
                f"As far as I know the {f.name} at the {where} is in service, but I can't "
                "check it from here."
            )
        elif len(people) == 1:
            p = self.office.person(people[0])
            where = self.office.location(p.location).name
            message = f"{p.name} works at {where}; I can't see whether they are there right now."
        else:
            thing = self.unknown_thing(piece.words)
            if not thing:
                message = f"I can't answer that from what I know. {self.capabilities()}"
                return Finding("question", piece, UNANSWERED, message=message)
            message = f"I don't know of any {thing} in this office."
        return Finding("question", piece, "a question, answered in words", message=message)

    def _item_question(self, piece: Piece, item: str, requester: str) -> Finding:
        t = self.office.item_type(item)
        owners = [o for o in self.office.owners_of(item, known_only=True) if o != requester]
        asked = [p for p in self._named(piece.text, "person") if p != requester]
        names = [self.office.person(o).name for o in owners[:4]]
        makers = [f for f in self.office.facilities if item in f.products]
        whose = ""
        a_thing = f"{_article(t.name)} {t.name}"
        if language.plural(t.name) == t.name:
            a_thing = f"some {t.name}"  # "scissors"
        if self._says_mine(piece.text, item):  # "did anyone find my umbrella?"
            answer = f"I don't know where your {t.name} is; I can't see it from here."
            return Finding("question", piece, "a question, answered in words", message=answer)
        if len(asked) == 1:  # "does Hope have a calculator?"
            who = self.office.person(asked[0]).name
            if asked[0] in owners:
                answer, whose = f"As far as I know, {who} has {a_thing}.", f"{who}'s"
            else:
                answer = f"As far as I know, {who} has no {t.name}."
        elif makers:
            where = self.office.location(makers[0].location).name
            answer = f"The {makers[0].name} at the {where} makes them."
        elif names:
            has = "has" if len(names) == 1 else "have"
            answer = f"As far as I know, {_listed(names)} {has} {a_thing}."
        else:
            answer = f"I don't know of anyone here with {a_thing}."
        if t.kind not in ("belonging", "product"):  # a document, a file: not for me to tell
            answer = f"I can't tell that about the {t.name} from what I know."
            return Finding("question", piece, "a question, answered in words", message=answer)
        verb = "get" if t.kind == "product" else "bring"
        shall = f"Shall I {verb} you one?"
        if self.acts.later(piece.words):  # "... I could use later?": not now unless told so
            shall = f"Shall I {verb} you one now, or would you rather tell me when?"
        return Finding(
            "question",
            piece,
            "a question that may be a request: answered, then asked",
            message=answer,
            offer=f"{verb} me {whose or _article(t.name)} {t.name}",
            shall=shall,
        )

    def _statement(self, piece: Piece, requester: str) -> Finding | None:
        if not piece.asks and self._context_fragment(piece):
            return Finding("statement", piece, "context beside the request")
        if piece.asks or not self.acts.statement(piece.words):
            return None
        named = tuple(self._stated_items(piece, requester)) + tuple(
            f"person:{p}" for p in self._named(piece.text, "person")[:1]
        )
        return Finding("statement", piece, "a statement, context only", context=named)

    def _context_fragment(self, piece: Piece) -> bool:
        """ "Tea time soon. Could you bring me a ruler?": a fragment with no request wording
        whose items only modify other words ("tea time"), beside a sentence that asks for
        something, is context; it never adds an errand of its own."""
        if self.acts.request(piece.words):
            return False
        others = [p for p in self._pieces if p is not piece and p.start > piece.end]
        if not any(self.acts.request(p.words) for p in others):
            return False
        tokens = self.lex.tokens(piece.text)
        mentions = self.lex.scan(tokens)
        items = [m for m in mentions if m.kind in ("item", "cue")]
        if not items or any(language.verb_lemmas(t.word) & self.lex.cue_words for t in tokens):
            return False
        modifying = modifiers(tokens, mentions)

        def compound(m: Mention) -> bool:  # "tea time": the item names a kind of time
            after = tokens[m.end].word if m.end < len(tokens) else ""
            return language.is_noun(after) and after not in self.en.courtesy

        return all(m.start in modifying or compound(m) for m in items)

    def _says_mine(self, text: str, item: str) -> bool:
        """ "did anyone find *my* umbrella?" (not "lend *me* a ruler": the asker's want)."""
        tokens = self.lex.tokens(text)
        mentions = self.lex.scan(tokens)
        return any(
            m.kind == "item"
            and m.ids == (item,)
            and n
            and mentions[n - 1].kind == "self"
            and tokens[mentions[n - 1].start].word in ("my", "mine")
            for n, m in enumerate(mentions)
        )

    def _stated_items(self, piece: Piece, requester: str) -> list[str]:
        """The items a statement names, as "item|whose": "my stapler" → stapler|my,
        "the book ... belongs to Yang" → book|Yang Lei's (a later "it" keeps its owner). An
        item that only modifies another ("wipes *for the cups*") is not what the statement is
        about, so a later "some" never means it."""
        tokens = self.lex.tokens(piece.text)
        mentions = self.lex.scan(tokens)
        words = [t.word for t in tokens]
        modifying = modifiers(tokens, mentions)
        out: list[str] = []
        for n, m in enumerate(mentions):
            if m.kind != "item" or len(m.ids) != 1 or m.start in modifying:
                continue
            before = mentions[n - 1] if n else None
            whose = ""
            if before is not None and before.kind == "self" and before.possessive:
                whose = "my"
            elif before is not None and before.kind == "person" and before.possessive:
                whose = f"{self.office.person(before.ids[0]).name}'s"
            elif before is not None and before.kind == "pronoun" and before.possessive:
                people = {p.ids for p in mentions[:n] if p.kind == "person" and len(p.ids) == 1}
                if len(people) == 1:  # "Yang said I could borrow his book"
                    whose = f"{self.office.person(next(iter(people))[0]).name}'s"
            elif (holder := _holder(mentions, n, words)) is not None:
                whose = f"{self.office.person(holder).name}'s"  # "Bram has a stopwatch"
            else:
                for k in range(len(words) - 1):
                    if words[k : k + 2] == ["belongs", "to"]:
                        owner = [x for x in mentions if x.kind == "person" and x.start > k]
                        if owner and len(owner[0].ids) == 1:
                            whose = f"{self.office.person(owner[0].ids[0]).name}'s"
            out.append(f"{m.ids[0]}|{whose}")
        return out

    def _negated(self, piece: Piece, requester: str) -> Finding | None:
        found = self._negation(piece)
        if found is not None:
            self._negating = True
            return found
        if self._negating and self._told_reason(piece):
            # "don't bother bringing the level, Otto's lending me his": why the errand is not
            # wanted, told as what is happening, not an errand of its own
            return Finding("negated", piece, "the reason the errand is not wanted")
        return None

    def _told_reason(self, piece: Piece) -> bool:
        """A piece after a negated errand that tells something (a finite verb, a contracted
        "'s") and asks nothing, with no request after it in the message."""
        told = any(language.is_finite_verb(w) for w in piece.words) or bool(
            re.search(r"\w['’](?:s|re|m|ve|ll)\b", piece.text)
        )
        later = [p for p in self._pieces if p.start >= piece.start]
        return told and not piece.asks and not any(self.acts.request(p.words) for p in later)

    def _negation(self, piece: Piece) -> Finding | None:
        words = piece.words
        for at in range(len(words)):
            for neg in self.en.negators:
                if not _starts_with(words, at, neg):
                    continue
                if at and words[at - 1] not in self.en.lead_in:
                    continue  # "I can't find my stapler": not the request verb
                if self._request_verb(words, at + len(neg) - 1):
                    return Finding(
                        "negated", piece, f"negated: {' '.join(neg)}"
                    )  # "no longer need"
                k = at + len(neg)
                while k < len(words):  # "don't actually need", "do not ever print"
                    if self._request_verb(words, k) or self._errand_gerund(words[k]):
                        return Finding("negated", piece, f"negated: not to {words[k]}")
                    if words[k] not in self.en.negation_fillers:
                        break
                    k += 1
        return None

    def _destructive(self, piece: Piece, requester: str) -> Finding | None:
        for sub in _sub_pieces(piece):
            at = sub.verb_at(self.en.lead_in)
            for verb in self.en.destructive:
                if verb[0] in self.lex.operation_words:
                    continue  # "shred my drafts" where a shredder is offered: a service
                if _starts_with(sub.words, at, verb):
                    said = " ".join(verb)
                    return Finding(
                        "destructive",
                        piece,
                        f"destructive: {said}",
                        message=(
                            f"Sorry, I won't {said} anything: I don't dispose of, damage or take "
                            f"people's things. {self.capabilities()}"
                        ),
                    )
        return None

    def _fact(self, piece: Piece, requester: str) -> Finding | None:
        tokens = self.lex.tokens(piece.text)
        mentions = self.lex.scan(tokens)
        k = 0
        while k < len(mentions) and mentions[k].kind == "word":
            if tokens[mentions[k].start].word not in self.en.fact_openers:
                return None
            k += 1
        if k < len(mentions) and mentions[k].kind == "self":
            return self._own_item_fact(piece, requester)
        if k >= len(mentions) or mentions[k].kind != "person" or len(mentions[k].ids) != 1:
            return None
        subject = mentions[k]
        person = subject.ids[0]
        rest = [t.word for t in tokens[subject.end :]]
        item: str | None = None
        if subject.possessive and k + 1 < len(mentions) and mentions[k + 1].kind == "item":
            item = mentions[k + 1].ids[0]
            rest = [t.word for t in tokens[mentions[k + 1].end :]]
        copula = next((c for c in self.en.copulas if _starts_with(rest, 0, c)), None)
        if copula is None and not (subject.possessive and item is None):
            return None  # "Wang's away" reads as a possessive: the copula is in the 's
        state = rest[len(copula) :] if copula else rest
        name = self.office.person(person).name
        if item is not None:
            cond = next((c for c in self.en.conditions if _starts_with(state, 0, c)), None)
            if cond is None:
                return None
            said = " ".join(cond)
            hint = Hint(
                kind="condition", person=person, value=said, item_type=item, said=piece.text
            )
            thing = self.office.item_type(item).name
            return Finding("fact", piece, f"a fact: {name}'s {thing} is {said}", hint)
        for phrase in self.en.away:
            if _starts_with(state, 0, phrase) and len(state) <= len(phrase) + 2:
                hint = Hint(kind="availability", person=person, value="away", said=piece.text)
                return Finding("fact", piece, f"a fact: {name} is away", hint)
        if state and state[0] in self.en.location_prepositions:
            place = self._place(piece.text)
            if place is not None:
                hint = Hint(kind="location", person=person, value=place, said=piece.text)
                where = self.office.location(place).name
                return Finding("fact", piece, f"a fact: {name} is at the {where}", hint)
        for phrase in self.en.here:
            if _starts_with(state, 0, phrase) and len(state) <= len(phrase) + 1:
                hint = Hint(kind="availability", person=person, value="here", said=piece.text)
                return Finding("fact", piece, f"a fact: {name} is here", hint)
        return None

    def _own_item_fact(self, piece: Piece, requester: str) -> Finding | None:
        """ "I can't find my stapler", "my stapler is broken": the requester's own item is out
        of use (so they want someone else's), said as a fact, not a request."""
        tokens = self.lex.tokens(piece.text)
        words = [t.word for t in tokens]
        items = [m for m in self.lex.scan(tokens) if m.kind == "item"]
        if len(items) != 1 or items[0].start == 0 or words[items[0].start - 1] != "my":
            return None
        before, after = words[: items[0].start - 1], words[items[0].end :]
        lost = any(
            _starts_with(before, n, p) for n in range(len(before)) for p in self.en.own_item_lost
        )
        copula = next((c for c in self.en.copulas if _starts_with(after, 0, c)), None)
        broken = copula is not None and any(
            _starts_with(after, len(copula), c) for c in self.en.conditions
        )
        if not (lost and before[:1] == ["i"]) and not (broken and not before):
            return None
        item = items[0].ids[0]
        hint = Hint(
            kind="condition", person=requester, value="missing", item_type=item, said=piece.text
        )
        thing = self.office.item_type(item).name
        return Finding("fact", piece, f"a fact: the requester's {thing} is out of use", hint)

    def _unsupported(self, piece: Piece, requester: str) -> Finding | None:
        found = self._unsupported_service(piece)
        if found is not None and self._own_doing(piece) and self._asked_elsewhere(piece):
            # "I need to pay the bill. Could you bring me a calculator?": what the speaker
            # will do themselves is context for the request beside it, not asked of me
            return Finding("statement", piece, "the speaker's own doing, context only")
        return found

    def _own_doing(self, piece: Piece) -> bool:
        """ "I need to pay ...", "we have to scan ...": the speaker's own activity ("to"
        and a verb after a first-person subject), not "I need you to ..."."""
        w = content(piece.words)
        if not w or w[0] not in self._self_words or set(w) & {"you", "u"}:
            return False
        return "to" in w[1:4]

    def _asked_elsewhere(self, piece: Piece) -> bool:
        return any(self.acts.request(p.words) for p in self._pieces if p is not piece)

    def _unsupported_service(self, piece: Piece) -> Finding | None:
        for sub in _sub_pieces(piece):
            words = sub.words
            at = sub.verb_at(self.en.lead_in)
            if at < len(words) and words[at] in self.en.service_verbs:
                verb = words[at]
                nxt = words[at + 1] if at + 1 < len(words) else ""
                ours = verb in self.lex.cue_words or verb in self._office_words
                if not ours or (verb not in self.lex.cue_words and nxt in _DETERMINERS):
                    return self._decline_service(piece, verb)
            cue = next((n for n, w in enumerate(words) if self._request_verb(words, n)), None)
            if cue is None:
                continue
            for n in range(cue + 1, len(words)):
                w = words[n]
                if w in self.en.modifier_prepositions or words[n - 1] in ("my", "our"):
                    break
                if w in self.en.service_products and w not in self._office_words:
                    if _possessive_of_name(piece.text, w, self._office_words):
                        continue  # "Chip's scanner": a colleague's, not "chips"
                    return self._decline_service(piece, w, product=True)
        return None

    def _decline_service(self, piece: Piece, word: str, *, product: bool = False) -> Finding:
        what = f"get you any {word}" if product else word  # "any": mass and count nouns alike
        return Finding(
            "unsupported",
            piece,
            f"not offered here: {word}",
            message=(
                f"Sorry, I can't {what}: nothing in this office offers that, and I won't "
                f"swap it for something else. {self.capabilities()}"
            ),
        )

    # -- rewrites ------------------------------------------------------------------------
    def _rewrite(
        self, text: str, hints: list[Hint], context: list[str]
    ) -> tuple[str, list[Evidence]]:
        evidence: list[Evidence] = []
        text, found = self._purposes(text)
        evidence += found
        for phrase in NEED_PHRASES:  # "Chen is looking for a pen": Chen needs a pen
            spaced = r"[\s']*".join(re.escape(w) for w in phrase)
            text = re.sub(rf"\b{spaced}\b", "needs", text, flags=re.IGNORECASE)
        subjects = {c.removeprefix("person:") for c in context if c.startswith("person:")}
        text = self._name_pronouns(text, hints, subjects)
        text, found = self._dangling_possessives(text)
        evidence += found
        said = [
            f"{h.item_type}|"
            for h in hints
            if h.kind == "condition" and h.item_type and h.value != "not wanted"
        ]
        stated = [c for c in context if not c.startswith("person:")]
        said += stated
        if said and not self._names_an_item(text):
            item, _, whose = said[-1].partition("|")
            thing = self.office.item_type(item).name
            # "the stapler is for Wang, bring it to him": "it" is the stated item, and
            # "Gao asked for my scissors, bring them to her": mine
            back = ("it", "them") if stated and said[-1] == stated[-1] else ()
            for phrase in (*self.en.another_one, "some", *back):
                pattern = re.compile(rf"\b{re.escape(phrase)}\b", re.IGNORECASE)
                match = pattern.search(text)
                if match:
                    kept = phrase in back and whose
                    said_as = f"{whose} {thing}" if kept else f"a {thing}"
                    meaning = said_as if kept else f"another {thing}"
                    evidence.append(Evidence(words=match.group(0), meaning=meaning))
                    text = text[: match.start()] + said_as + text[match.end() :]
                    break
            else:
                text, found = self._container_of(text, thing)
                evidence += found
        return text, evidence

    def _container_of(self, text: str, thing: str) -> tuple[str, list[Evidence]]:
        """ "I ran out of forms. Could you bring me a box?": a noun this office does not know,
        asked for right after a statement that named an item, is a quantity of that item."""
        pattern = re.compile(r"\b(?:a|an|one|another)\s+([a-z]+)\b", re.IGNORECASE)
        for match in pattern.finditer(text):
            noun = match.group(1).lower()
            if self._names_at(text[match.start(1) :]) or not language.is_noun(noun):
                continue
            if language.zipf(noun) < 3 or noun in ("one", "bit", "lot"):
                continue
            if _compound_head(text[match.end() :]):
                continue  # "a power bank": a thing of its own, not a quantity of the item
            evidence = [Evidence(words=match.group(0), meaning=f"a {noun} of {thing}")]
            return text[: match.start()] + f"a {thing}" + text[match.end() :], evidence
        return text, []

    def _names_at(self, text: str) -> bool:
        """Whether ``text`` opens with a name of this office ("lunch box", "Sun Li"); a word
        that is only part of one ("box" of "lunch box") is not."""
        mentions = self.lex.scan(self.lex.tokens(text))
        return bool(mentions) and mentions[0].start == 0 and mentions[0].kind != "word"

    def _dangling_possessives(self, text: str) -> tuple[str, list[Evidence]]:
        """ "lend him mine", "give him Rich's": a possessive with no item after it means the
        item named last before it (in what is left, else in the whole message)."""
        evidence: list[Evidence] = []

        def last_item(before: str) -> str | None:
            for said in (before, self._text):
                items = [m for m in self.lex.scan(self.lex.tokens(said)) if m.kind == "item"]
                if items:
                    return self.office.item_type(items[-1].ids[0]).name
            return None

        def whole(match: re.Match[str]) -> str:
            word = match.group(1)
            owner = re.sub(r"['’]s$", "", word)
            if word.lower() != "mine" and not self._is_person_word(owner):
                return word
            thing = last_item(text[: match.start()])
            if thing is None:
                return word
            said = f"my {thing}" if word.lower() == "mine" else f"{word} {thing}"
            evidence.append(Evidence(words=word, meaning=said))
            return said

        pattern = re.compile(
            r"\b(mine|\w+['’]s)(?=\s*(?:[,.!?;]|$|\s+(?:please|too|instead|then|if|and|or|"
            r"for now|for a bit|for today)\b))",
            re.IGNORECASE,
        )
        return pattern.sub(whole, text), evidence

    def _is_person_word(self, word: str) -> bool:
        tokens = self.lex.tokens(word)
        return any(m.kind == "person" for m in self.lex.scan(tokens))

    def _name_pronouns(self, text: str, hints: list[Hint], subjects: set[str]) -> str:
        """ "Zhang is at his desk. Get him to sign ...", "Pat hurt her hand, take her my ice
        pack": with the fact taken out, a pronoun that can only mean the one person it named
        gets the name back."""
        people = {h.person for h in hints if h.kind in ("availability", "location", "condition")}
        people |= subjects
        if len(people) != 1:
            return text
        name = self.office.person(next(iter(people))).name

        def named(match: re.Match[str]) -> str:
            word, gap, following = match.group(1).lower(), match.group(2), match.group(3)
            possessive = word == "his" or (word == "her" and normalize(following) in self.lex.items)
            return (f"{name}'s" if possessive else name) + gap + following

        return re.sub(r"\b(him|his|her)\b(\s*)(\w*)", named, text, flags=re.IGNORECASE)

    def _purposes(self, text: str) -> tuple[str, list[Evidence]]:
        heads = "|".join(re.escape(h) for h in sorted(self.en.purpose_heads, key=len, reverse=True))
        links = "|".join(re.escape(h) for h in sorted(self.en.purpose_links, key=len, reverse=True))
        pattern = re.compile(
            rf"\b(?:{heads})\s+(?:{links})\s+([a-z]+)((?:\s+[a-z0-9]+)*)", re.IGNORECASE
        )
        evidence: list[Evidence] = []
        match = pattern.search(text)
        if match is None:
            return text, evidence
        verb = _stem(match.group(1).lower())
        tail = match.group(2).split()
        keep = 0
        while keep < len(tail) and tail[keep].lower() in self.en.purpose_tail:
            keep += 1
        used_tail = " ".join(tail[:keep])
        end = match.start(2) + (
            len(match.group(2)) - len(match.group(2).lstrip()) + len(used_tail) if keep else 0
        )
        following = tail[0].lower() if tail else ""

        def declared(phrase: str) -> list[str]:
            return [t.name for t in self.office.item_types if phrase in map(_purpose, t.purposes)]

        # "to write on" (paper) before "to write" (pen, "to write with")
        types = declared(f"{verb} {following}") if following else []
        types = types or declared(verb)
        if len(types) != 1:
            return text, evidence  # none or several: the parser asks which item
        name = types[0]
        evidence.append(Evidence(words=text[match.start() : end], meaning=f"a {name} (to {verb})"))
        return text[: match.start()] + f"a {name}" + text[end:], evidence

    # -- helpers -------------------------------------------------------------------------
    def _request_verb(self, words: list[str], at: int) -> bool:
        w = words[at]
        return w in self.lex.cue_words or (
            w in self.en.service_verbs and (at + 1 >= len(words) or words[at + 1] in _DETERMINERS)
        )

    def _errand_gerund(self, word: str) -> bool:
        """An errand's verb as a gerund ("bringing", "fetching"), where a negation passed on
        by "bother" or "trouble yourself" lands."""
        return word.endswith("ing") and bool(language.verb_lemmas(word) & self.lex.cue_words)

    def _names_an_item(self, text: str) -> bool:
        return any(m.kind == "item" for m in self.lex.scan(self.lex.tokens(text)))

    def _named(self, text: str, kind: str) -> list[str]:
        """The ids of the people, items or facilities a text names, in order."""
        tokens = self.lex.tokens(text)
        mentions = self.lex.scan(tokens)
        found: list[str] = []
        for n, m in enumerate(mentions):
            word = tokens[m.start].word
            if m.kind == kind and len(m.ids) == 1:
                found.append(m.ids[0])
            elif kind == "item" and m.kind == "cue" and word in self.lex.items:
                if n and mentions[n - 1].possessive:  # "Mao's seal": the item, not the verb
                    found.append(self.lex.items[word])
        return list(dict.fromkeys(found))

    @property
    def _self_words(self) -> frozenset[str]:
        return frozenset({"i", "me", "my", "we", "us", "our", "im", "id", "ive"})

    def unknown_thing(self, words: list[str]) -> str:
        """ "a tape measure" in "who has a tape measure": the words after an article that
        name no item of this office."""
        for n, w in enumerate(words):
            if w in ("a", "an", "any", "some"):
                rest = []
                for x in words[n + 1 :]:
                    if x in _DETERMINERS or x in self.en.modifier_prepositions or x in ("i", "me"):
                        break
                    rest.append(x)
                return " ".join(rest[:3])
        return ""

    def _place(self, text: str) -> str | None:
        """The location a fact names: a facility's, or a location by its name."""
        mentions = self.lex.scan(self.lex.tokens(text))
        for m in mentions:
            if m.kind == "facility":
                return self.office.facility(m.ids[0]).location
        lowered = " ".join(_words(text))
        for loc in self.office.locations:
            if " ".join(_words(loc.name)) in lowered:
                return loc.id
        return None

    def capabilities(self) -> str:
        """What this office lets the assistant do, in words, from the office file."""
        things = [t.name for t in self.office.item_types if t.kind == "belonging"]
        machines = [
            f.name
            for f in self.office.facilities
            if any(self.office.runnable(o) for o in f.operations)
        ]
        parts = []
        if things:
            parts.append(f"fetch and deliver things like {_listed(things[:5])}")
        parts.append("pass on files")
        if machines:
            parts.append(f"run errands at the {_listed(machines)}")
        return f"What I can do here: {_listed(parts)}."


def _unnoted(reply: str) -> str:
    """ "Noted; I'll keep it in mind." → "I'll keep it in mind." (said once already)."""
    rest = reply.removeprefix("Noted; ")
    return rest[:1].upper() + rest[1:] if rest != reply else reply


def _article(noun: str) -> str:
    return "an" if noun[:1].lower() in "aeiou" else "a"


def _listed(words: list[str]) -> str:
    return words[0] if len(words) == 1 else ", ".join(words[:-1]) + " and " + words[-1]


RequestScreen.RULES = (
    ("withdrawn", RequestScreen._withdrawn),
    ("note", RequestScreen._note),
    ("exclusion", RequestScreen._exclusion),
    ("wish", RequestScreen._wish),
    ("thanks", RequestScreen._thanks),
    ("condition", RequestScreen._condition),
    ("negated", RequestScreen._negated),
    ("destructive", RequestScreen._destructive),
    ("fact", RequestScreen._fact),
    ("question", RequestScreen._question),
    ("statement", RequestScreen._statement),
    ("unsupported", RequestScreen._unsupported),
)
UNANSWERED = "a question I cannot answer"
# What asks nothing of the assistant: an aside beside it ("..., all sorted") is no request.
_SAYS_NOTHING_TO_DO = frozenset(
    {"thanks", "wish", "withdrawn", "note", "condition", "fact", "statement"}
)
_DROPPED = frozenset(
    {
        "note",
        "condition",
        "negated",
        "fact",
        "withdrawn",
        "exclusion",
        "wish",
        "thanks",
        "question",
        "statement",
    }
)


def _stem(word: str) -> str:
    """'cutting' → 'cut', 'writes' → 'write', 'stapling' → 'staple' (the verb's lemma, from
    the morphology library; a word it does not know as a verb stays as it is)."""
    w = word.lower()
    found = language.verb_lemmas(w)
    return min(found, key=len) if found else w


def _purpose(phrase: str) -> str:
    first, _, rest = phrase.lower().partition(" ")
    return f"{_stem(first)} {rest}".strip()


def _pieces(text: str) -> list[Piece]:
    """Sentences, and the comma-separated parts of each."""
    out: list[Piece] = []
    pos = 0
    for m in [*_SENTENCE_END.finditer(text), None]:
        end = m.start() if m is not None else len(text)
        sentence_start = pos
        sub = 0
        for b in [*re.finditer(",", text[sentence_start:end]), None]:
            stop = sentence_start + (b.start() if b is not None else end - sentence_start)
            chunk = text[sentence_start + sub : stop]
            lead = len(chunk) - len(chunk.lstrip())
            piece_text = chunk.strip()
            if piece_text:
                start = sentence_start + sub + lead
                asks = b is None and m is not None and "?" in m.group(0)  # its last part
                out.append(
                    Piece(piece_text, start, start + len(piece_text), _words(piece_text), asks)
                )
            if b is not None:
                sub = b.end()
        pos = m.end() if m is not None else len(text)
    return out


def _sub_pieces(piece: Piece) -> list[Piece]:
    """The parts of a piece joined by "and"/"then"/"but", for finding each one's verb."""
    out: list[Piece] = []
    pos = 0
    for m in [*_PIECE_BREAK.finditer(piece.text), None]:
        end = m.start() if m is not None else len(piece.text)
        chunk = piece.text[pos:end]
        if chunk.strip():
            out.append(Piece(chunk, piece.start + pos, piece.start + end, _words(chunk)))
        pos = m.end() if m is not None else len(piece.text)
    return out


def _without(text: str, cut: int, dropped: list[Piece]) -> str:
    """The text from ``cut`` on, with the dropped pieces blanked out."""
    chars = list(text)
    for n in range(min(cut, len(chars))):
        chars[n] = " "
    for p in dropped:
        for n in range(p.start, p.end):
            chars[n] = " "
    left = "".join(chars)
    # punctuation left stranded by a removed piece: ", ," or a leading comma
    left = re.sub(r"(^|[.!?;])[\s,]*,", r"\1", left)
    left = re.sub(r",\s*(?=[.!?;]|$)", "", left)
    return re.sub(r"\s+", " ", left).strip(" ,")


def _possessive_of_name(text: str, word: str, office_words: frozenset[str]) -> bool:
    """Whether ``word`` ("chips") is how a name's possessive ("Chip's") was folded."""
    if not word.endswith("s") or word[:-1] not in office_words:
        return False
    return re.search(rf"\b{re.escape(word[:-1])}['’]s\b", text, re.IGNORECASE) is not None


_POSSESSION_VERBS = english_words("possession_verbs")


def _holder(mentions: list[Mention], n: int, words: list[str]) -> str | None:
    """The one person a statement says has the item ``mentions[n]`` ("Bram has a stopwatch",
    "Femi's got a spare radio"): a later "it" is theirs, not another of its kind."""
    people = [m for m in mentions[:n] if m.kind == "person" and len(m.ids) == 1]
    if len(people) != 1:
        return None
    between = words[people[0].end : mentions[n].start]
    verb = between[:1] if not people[0].possessive else ["has"]  # "Femi's got": has got
    return people[0].ids[0] if verb and verb[0] in _POSSESSION_VERBS else None


def _compound_head(after: str) -> bool:
    """Whether the word right after a noun is a noun that heads a compound with it ("a power
    *bank*"), not a time word or a courtesy ("a box today", "a box please")."""
    nxt = language.words(after)[:1]
    if not nxt or not after[:1].isspace():
        return False
    found = language.lemmas(nxt[0])
    return "NOUN" in found and "ADV" not in found


def _has_words(text: str) -> bool:
    return bool(_WORD.search(text))
