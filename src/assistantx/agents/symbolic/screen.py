"""The request screen: ask or decline, never guess — before any task is read from a request.

A request is cut into pieces (sentences, and the comma/"and"/"then" parts of one); a table of
rules, tried in priority order, says what each piece is. The first rule that matches a piece
decides it:

==============  ==================================================================  ==========
rule            matches                                                             effect
==============  ==================================================================  ==========
withdrawn       "never mind", "forget it", "cancel that"                            drops all
                                                                                    said before
negated         "don't bring me ...", "no need to print ..."                        drops piece
destructive     "throw away Wang's stapler", "hide ...", "get rid of ..."           declines
fact            "Wang is away", "Zhang is in the meeting room",                     a hint;
                "Zhang's stapler is broken"                                         drops piece
unsupported     a service the office does not offer ("scan my contract",            declines
                "make me a cup of tea")
==============  ==================================================================  ==========

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
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Literal

from assistantx.agents.symbolic._lexicon import Lexicon
from assistantx.core.english import entries_of
from assistantx.core.english import words as english_words
from assistantx.core.office import Office
from assistantx.core.task_schema import DeclineOutcome, Evidence, Hint
from assistantx.memory.names import normalize

_WORD = re.compile(r"[A-Za-z0-9]+(?:['’][A-Za-z]+)?")
_SENTENCE_END = re.compile(r"[.!?;\n]+")
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
    )


def _words(text: str) -> list[str]:
    return [w.lower().replace("'", "").replace("’", "") for w in _WORD.findall(text)]


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

    def verb_at(self, lead_in: frozenset[str]) -> int:
        """Index of the request's verb: the first word that is no lead-in ("could you ...")."""
        return next((n for n, w in enumerate(self.words) if w not in lead_in), len(self.words))


Verdict = Literal["withdrawn", "negated", "destructive", "fact", "unsupported"]


@dataclass(frozen=True)
class Finding:
    verdict: Verdict
    piece: Piece
    meaning: str  # in words, for the evidence
    hint: Hint | None = None
    message: str = ""  # for a decline


@dataclass
class Screened:
    """What the screen made of a request."""

    text: str  # what is left for the frame parser
    decline: str | None = None
    outcome: DeclineOutcome = "unachievable"
    hints: list[Hint] = field(default_factory=list)
    evidence: list[Evidence] = field(default_factory=list)


Rule = Callable[["RequestScreen", Piece, str], "Finding | None"]


class RequestScreen:
    """Screens requests against one office (its people, items, facilities and purposes)."""

    def __init__(self, office: Office, lex: Lexicon) -> None:
        self.office = office
        self.lex = lex
        self.en = english()
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
        pieces = _pieces(text)
        findings: list[Finding] = []
        for piece in pieces:
            for _, rule in self.RULES:
                found = rule(self, piece, requester)
                if found is not None:
                    findings.append(found)
                    break
        out = Screened(text=text)
        out.evidence = [Evidence(words=f.piece.text, meaning=f.meaning) for f in findings]
        out.hints = [f.hint for f in findings if f.hint is not None]
        withdrawn = [f for f in findings if f.verdict == "withdrawn"]
        cut = withdrawn[-1].piece.end if withdrawn else 0
        live = [f for f in findings if f.piece.start >= cut]
        declines = [f for f in live if f.verdict in ("destructive", "unsupported")]
        if declines:
            out.decline, out.outcome = declines[0].message, "unachievable"
            return out
        dropped = [f.piece for f in findings if f.verdict in ("negated", "fact", "withdrawn")]
        left = _without(text, cut, dropped)
        if not set(_words(left)) - self.en.courtesy:
            negated = [f for f in live if f.verdict == "negated"]
            if withdrawn and not negated:
                out.decline = "OK, I've dropped that request. I did nothing."
                out.outcome = "done"
                return out
            if negated:
                said = "; ".join(repr(f.piece.text) for f in negated)
                out.decline = (
                    f"OK, I won't do that (you wrote {said}). I did nothing; "
                    "tell me if you do need something."
                )
                out.outcome = "done"
                return out
        left, rewrites = self._rewrite(left, out.hints)
        out.evidence += rewrites
        out.text = left
        return out

    # -- rules ---------------------------------------------------------------------------
    def _withdrawn(self, piece: Piece, requester: str) -> Finding | None:
        words = [w for w in piece.words if w not in ("actually", "oh", "ok", "okay", "please")]
        if tuple(words) in self.en.withdraw:
            return Finding("withdrawn", piece, "withdraws the request")
        return None

    def _negated(self, piece: Piece, requester: str) -> Finding | None:
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
                    if self._request_verb(words, k):
                        return Finding("negated", piece, f"negated: not to {words[k]}")
                    if words[k] not in self.en.negation_fillers:
                        break
                    k += 1
        return None

    def _destructive(self, piece: Piece, requester: str) -> Finding | None:
        for sub in _sub_pieces(piece):
            at = sub.verb_at(self.en.lead_in)
            for verb in self.en.destructive:
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
    def _rewrite(self, text: str, hints: list[Hint]) -> tuple[str, list[Evidence]]:
        evidence: list[Evidence] = []
        text, found = self._purposes(text)
        evidence += found
        text = self._name_pronouns(text, hints)
        broken = [h for h in hints if h.kind == "condition" and h.item_type]
        if broken and not self._names_an_item(text):
            thing = self.office.item_type(broken[-1].item_type or "").name
            for phrase in (*self.en.another_one, "some"):
                pattern = re.compile(rf"\b{re.escape(phrase)}\b", re.IGNORECASE)
                match = pattern.search(text)
                if match:
                    evidence.append(Evidence(words=match.group(0), meaning=f"another {thing}"))
                    text = text[: match.start()] + f"a {thing}" + text[match.end() :]
                    break
        return text, evidence

    def _name_pronouns(self, text: str, hints: list[Hint]) -> str:
        """ "Zhang is at his desk. Get him to sign ...": with the fact taken out, a pronoun
        that can only mean the one person it named gets the name back."""
        people = {h.person for h in hints if h.kind in ("availability", "location")}
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

    def _names_an_item(self, text: str) -> bool:
        return any(m.kind == "item" for m in self.lex.scan(self.lex.tokens(text)))

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


def _listed(words: list[str]) -> str:
    return words[0] if len(words) == 1 else ", ".join(words[:-1]) + " and " + words[-1]


RequestScreen.RULES = (
    ("withdrawn", RequestScreen._withdrawn),
    ("negated", RequestScreen._negated),
    ("destructive", RequestScreen._destructive),
    ("fact", RequestScreen._fact),
    ("unsupported", RequestScreen._unsupported),
)


def _stem(word: str) -> str:
    """'cutting' → 'cut', 'writes' → 'write', 'stapling' → 'staple' (enough for purposes)."""
    w = word.lower()
    if w.endswith("ing") and len(w) > 5:
        w = w[:-3]
        if len(w) > 2 and w[-1] == w[-2]:
            w = w[:-1]
    elif w.endswith("s") and not w.endswith("ss") and len(w) > 3:
        w = w[:-1]
    return w.removesuffix("e")


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
                out.append(Piece(piece_text, start, start + len(piece_text), _words(piece_text)))
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


def _has_words(text: str) -> bool:
    return bool(_WORD.search(text))
