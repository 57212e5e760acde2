"""A correction right after a name ("bring me Rich's clipboard - sorry, I meant Dawn's",
"..., no wait, Dawn's") replaces the person or item it corrects, before the pieces are judged."""

from __future__ import annotations

import re
from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.screen.english import DETERMINERS
from assistantx.agents.symbolic.reading.screen.rewrites import purposes
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language
from assistantx.core.needed_instead import needer_end
from assistantx.core.task_schema import Evidence

# "sorry, I meant ...", "no wait, ...", "on second thoughts, ...", "..., no, a pen", "I mean
# ...", "... actually, make it a pen", "- sorry, make that a water", ". actually no, Ben's":
# the words after it correct what was just said (only when they name one person or item,
# ``corrected``)
_CORRECTION = re.compile(
    r"(?:[,;.!?…]|\s[-–—]+)\s*"
    r"(?:(?:actually,?\s+)?(?:or\s+rather|sorry|oops|no wait|wait no|oh wait|no sorry|"
    r"sorry no|nope|nah|on\s+second\s+thoughts?|no(?=[,!.]))\b"
    r"[,!.]?\s*(?:i\s+mean[t]?\b|meant\b)?(?:[,]?\s*(?:actually,?\s*)?make\s+(?:it|that)\b)?"
    r"|i\s+mean[t]?\b|(?:actually,?\s*)?make\s+(?:it|that)\b"
    # "..., change that to a snack", "... - actually, switch it for a water"
    r"|(?:actually,?\s*)?(?:change|switch|swap)\s+(?:it|that)\s+(?:to|for)\b"
    # "..., actually a snack instead": a thing, then "instead"
    r"|actually,?(?=\s+(?:an?\s+|some\s+|the\s+)?[^\W\d_]+(?:\s+[^\W\d_]+)?\s+instead\b)"
    # ". actually Lee's, ...", ". Actually, Lin.": one word, a pause or the end after it (only
    # a person or an item said so corrects, ``_corrected``)
    r"|actually,?(?=\s+(?:an?\s+|some\s+|the\s+)?[^\W\d_]+(?:['’]s)?\s*(?:[,.!?;…]|\s[-–—]|$)))"
    r"[,:]?\s*",
    re.IGNORECASE,
)
# "sorry, forget the coffee": dropped, not corrected to the coffee
_WITHDRAWING = tuple(tuple(p.split()) for p in english.entries("correction_withdrawals"))
# "make that a snack *from the vending machine*": where the corrected thing comes from
_SOURCES = tuple(tuple(p.split()) for p in english.entries("correction_sources"))
# "bring me the… actually, just print it", "... - actually, ...": after a trailing-off or a
# dash, "actually" corrects too.
_ELLIPSIS_ACTUALLY = re.compile(
    r"(?:\.{2,}|…|\s[-–—]+)\s*actually\b[,:]?\s*(?:no\b[,.!]?\s*)?", re.IGNORECASE
)
# The words before a correction's own request verb ("just", "please", "rather").
_FILLERS = frozenset(
    {"just", "please", "rather", "instead", "simply", "only", "can", "you", "could", "actually"}
)
_SENTENCE_END = re.compile(r"[.!?;\n]+|\s[-–—]+\s")
# Where a sentence goes on to a request of its own: "..., and then ...", "..., can you ...".
_NEXT_REQUEST = re.compile(
    r"(?:,\s*|\s+)(?:and\s+)?then\s+|,\s*(?:and\s+)?(?=(?:can|could|would|will)\s+you\b)",
    re.IGNORECASE,
)
_TRAILING = " .…,;-–—"
REPLACED = "means "  # the evidence's meaning where a person or item said was replaced


# The name said first and "I mean" after it, or the name with the speaker refused after it,
# in a sentence of its own after the request ("... his drill? Grant Okoro I mean", "...
# Grant Okoro, not me lol"): the same correction as "I mean Grant Okoro".
_NAME_THEN_MEANT = re.compile(
    r"(?P<end>[.!?;…]|\s[-–—]+)\s*\(?\s*(?P<name>[^\W\d_][\w'’-]*(?:\s+[^\W\d_][\w'’-]*){0,2}?)"
    r"(?:\s+i\s+mean[t]?\b|(?=,?\s+not\s+me\b))",
    re.IGNORECASE,
)


# "... sorry, not Lee - Lin", "... Not Lee, Lin.", "..., not Lee but Lin", "... Lee, no, Lin":
# a person refused after a request, then who is meant instead (a name, or "mine"/"me"), with
# or without "sorry" before it; read as "sorry, not Lee, Lin" when both sides are people
_NAME = r"[^\W\d_][\w'’-]*(?:\s+[^\W\d_][\w'’-]*){0,2}?"
_NOT_THEN_SAID = re.compile(
    r"(?P<lead>[,;.!?…]|\s[-–—]+)\s*"
    r"(?:(?:sorry|oops|actually|no|nope|oh)\b(?:[,!.]|\s*[-–—]+)?\s*)*"
    rf"(?:not\s+(?P<old>{_NAME})(?:\s*[,;:/]\s*|\s+[-–—]+\s*|\s+but\s+(?:rather\s+)?)"
    rf"|(?P<again>{_NAME})\s*,?\s+no\b[,!.]?\s*)"
    rf"(?P<new>{_NAME})\s*(?=[.!?;,]|\s[-–—]|$)",
    re.IGNORECASE,
)
# The words of the speaker said as whom a correction means instead ("not Lee's - mine")
_SELF_CORRECTED = frozenset({("mine",), ("me",), ("myself",), ("my", "own")})


def _not_then_said(terms: Terms, text: str) -> str:
    """ "Send Lee my file. sorry, not Lee - Lin Tao", "... Not Lee, Lin Tao", "..., not Lee
    but Lin Tao", "... Lee, no, Lin Tao": a person named earlier in the message refused, then
    one person (or the speaker) said in their place, is the correction "sorry, not Lee, Lin
    Tao"; anything else refused ("not today - tomorrow") is left as said."""
    for found in _NOT_THEN_SAID.finditer(text):
        before = text[: found.start()]
        old = found.group("old") or found.group("again")
        new = found.group("new")
        refused = [m for m in terms.lex.scan(terms.lex.tokens(old)) if m.kind == "person"]
        said = terms.lex.tokens(new)
        if len(refused) != 1 or len(terms.lex.tokens(old)) != refused[0].end:
            continue
        if not spellings(terms, "person", old) & spellings(terms, "person", before):
            continue  # the person refused was never named before
        if tuple(t.word for t in said) not in _SELF_CORRECTED:
            people = [m for m in terms.lex.scan(said) if m.kind == "person"]
            if len(people) != 1 or people[0].start or people[0].end != len(said):
                continue
        lead = found.group("lead")
        if found.group("again") and lead not in ".!?;…":
            continue  # "Lee, no, Lin" only as a sentence of its own
        return f"{before}{lead} sorry, not {old}, {new}{text[found.end() :]}"
    return text


# A correction's words said right after a word, with no pause ("a pen no wait a stapler", "a
# pen or rather a pencil"), and "actually" right before a thing said anew ("a pen actually a
# stapler"): the pause is put back, so it reads as the punctuated correction.
_UNPAUSED = re.compile(
    r"(?<=\w)\s+(?=(?:"
    + "|".join(
        r"\s+".join(re.escape(w) for w in p.split())
        for p in sorted(english.entries("unpaused_corrections"), key=len, reverse=True)
    )
    + r")\b)"
    # "actually" after a copula says what is so ("it's actually a stapler i need"), no mind
    # changed
    r"|(?<=\w)(?<!\bis)(?<![’']s)(?<!\bwas)(?<!\bare)\s+(?=actually\s+(?:an?|some)\s)",
    re.IGNORECASE,
)


# "bring me Wang's stapler no Zhang's": a thing said with its owner's "'s", then "no" and
# another owner's "'s" with no pause: the "no" corrects the owner, as ", no, Zhang's" does
_UNPAUSED_OWNER_NO = re.compile(
    r"(\b[^\W\d_]+['’]s(?:\s+[^\W\d_]+){1,3})\s+no\s+(?=[^\W\d_][\w-]*['’]s\b)",
    re.IGNORECASE,
)
# "no wait, also a pen": a correction's words that add a thing to the request, not replace
_ADDING = english.words("added_words")


def _paused(text: str) -> str:
    """``text`` with a comma before each correction said with no pause before it."""
    return _UNPAUSED_OWNER_NO.sub(r"\1, no, ", _UNPAUSED.sub(", ", text))


def _purposes_named(terms: Terms, text: str) -> str:
    """``text`` with each thing said by its purpose ("something to cut with") as the office's
    item declared for it, where one is: a correction says one thing in place of another."""
    for _ in range(4):
        fixed, found = purposes(terms, text)
        if not found:
            break
        text = fixed
    return text


def corrected(terms: Terms, text: str) -> tuple[str, list[Evidence]]:
    """ "bring me Rich's clipboard - sorry, I meant Dawn's", "..., no wait, Dawn's": a
    correction of one person or item right after it is said replaces it; the retracted
    one is never acted on (nor is the whole message dropped as withdrawn). The name said
    before "I mean", or before "not me", in a sentence of its own is the same correction;
    so is a person refused, then another said ("..., not Lee - Lin Tao"). A correction
    said with no pause before it is the same; a thing said by its purpose on either side of
    one ("something to write with, no wait, something to cut with") is the item for it."""
    text = _paused(text)
    if _CORRECTION.search(text):
        text = _purposes_named(terms, text)
    text = _not_then_said(terms, text)
    found = _NAME_THEN_MEANT.search(text)
    if found is not None and not _CORRECTION.search(text[: found.start("name")]):
        said = found.group("name")
        mentions = [m for m in terms.lex.scan(terms.lex.tokens(said)) if m.kind == "person"]
        if len(mentions) == 1 and len(mentions[0].ids) == 1:
            turned = f"{text[: found.end('end')]} I mean {said}{text[found.end() :]}"
            fixed, evidence = _corrected(terms, turned)
            if evidence:
                return fixed, evidence
    return _corrected(terms, text)


def _corrected(terms: Terms, text: str) -> tuple[str, list[Evidence]]:
    # the first to start: "fetch X... actually, no, just print" is corrected at "actually"
    found = [m for m in (_CORRECTION.search(text), _ELLIPSIS_ACTUALLY.search(text)) if m]
    if not found:
        return text, []
    match = min(found, key=lambda m: m.start())
    before, after = text[: match.start()], text[match.end() :]
    # "no wait sorry, a pen": more words of correcting before what is said anew
    after = _MORE_MARKS.sub("", after, count=1) or after
    after = _last_of_chain(after)
    # the correction ends at its sentence's end or at a comma: what follows is said beside it
    # ("... I meant Mao's seal, Wang needs hers today": the reason, read as a piece of its own)
    fix = re.split(r"[,.!?;\n]|\s[-–—]+\s", after, maxsplit=1)[0]
    rest = after[len(fix) :]
    tokens = terms.lex.tokens(fix)
    told = _what_it_is(terms, tokens, rest)
    if told:
        # "no wait, it's the paper one, photocopy it instead": what the thing is, said
        # before the request that corrects; the request is the correction
        fix = re.split(r"[,.!?;\n]|\s[-–—]+\s", rest[1:], maxsplit=1)[0]
        after, rest = rest[1:].lstrip(), rest[1 + len(fix) :]
        tokens = terms.lex.tokens(fix)
    elif _why_ruled_out(terms, tokens):
        # "Wang's stapler, no wait she's using it on the filing. Zhang's then": why the one
        # said is ruled out, then who or what instead; the choice after it is the correction
        # (before, "no wait" and the reason were read as withdrawing the whole request)
        chosen = _choice_after_reason(terms, rest)
        if chosen is not None:
            fix, rest = chosen
            tokens = terms.lex.tokens(fix)
    words = [t.word for t in tokens]
    if any(tuple(words[: len(w)]) == w for w in _WITHDRAWING):
        return text, []  # "sorry, forget the coffee": a withdrawal, read as one
    if words and words[0] in _ADDING:
        # "bring me a stapler. no wait, also a pen": the thing said is added to the request,
        # nothing it said is replaced; read as "bring me a stapler. also a pen"
        lead = text[match.start() : match.end()].lstrip()[:1]
        joined = lead if lead in ".!?;" else ","
        return f"{before.rstrip()}{joined} {after.lstrip()}", []
    refused: Sequence[Token] = ()
    if tokens and tokens[0].word == "not" and rest.startswith(","):
        # "no wait not rob's, Kiz's one": what is rejected first, then what replaces it
        refused = tokens[1:]
        fix = re.split(r"[,.!?;\n]|\s[-–—]+\s", rest[1:], maxsplit=1)[0]
        rest = rest[1 + len(fix) :]
        tokens = terms.lex.tokens(fix)
    if opens_request(terms, tokens):
        # "fetch Bill's tripod... actually, no, just print my draft": a correction that
        # says a request of its own withdraws the request it breaks off; the withdrawn
        # verb never runs (what came before that request's sentence stays)
        trimmed = before.rstrip(_TRAILING)
        last = _SENTENCE_END.split(trimmed)[-1]
        # "could my jacket get steamed, and then can you heat... no sorry, just bring my
        # lunch": only the request broken off is withdrawn, not an earlier one beside it
        last = _NEXT_REQUEST.split(last)[-1]
        cut = trimmed.rfind(last) if last else len(before)
        # "print my slides and take them to Ivo - sorry, I meant take it to Amber": a
        # correction that says again a later part of the request (its verb) replaces only
        # that part; the print still stands
        cut = _part_said_again(tokens, before, cut)
        meaning = f"withdraws {before[cut:].strip()!r}, asks instead"
        # "just bring my lunch": the adverb said only of the correction; after "and then"
        # the request reads plainly
        after = re.sub(r"^(?:(?:just|simply|rather|instead)\s+)+", "", after, flags=re.IGNORECASE)
        after = thing_kept(terms, before[cut:], tokens, after)
        return before[:cut] + after, [
            Evidence(words=text[match.start() :].strip(), meaning=meaning)
        ]
    if refused and tuple(t.word for t in tokens) in _SELF_CORRECTED:
        return _to_speaker(terms, text, match.start(), before, refused, rest)
    # "..., sorry, his laser, not the ruler": what is rejected after it says which one
    # the correction replaces; the correction itself is the part before "not"
    cut = next((k for k, t in enumerate(tokens) if t.word == "not" and k), len(tokens))
    tokens, rejected = tokens[:cut], [*refused, *tokens[cut:]]
    tokens, source = _source_kept(tokens, fix)
    needer = needer_end([t.word for t in tokens])
    if needer is not None:
        # "no wait, Zhang needs it first": who needs the thing is who it goes to instead
        tokens = tokens[:needer]
    if not tokens or len(tokens) > 5:
        return text, []
    mentions = [m for m in terms.lex.scan(tokens) if m.kind in ("person", "item")]
    if not mentions and not rejected:
        moved = _place_corrected(terms, tokens, before, rest)
        if moved is not None:
            return moved[0], [
                Evidence(words=text[match.start() :].strip(), meaning=f"{REPLACED}{moved[1]}")
            ]
    alone = not mentions  # "sorry not sam, robin": a name word read as the ordinary word
    if alone:
        mentions = _name_said_alone(terms, tokens)
    if len(mentions) == 2 and _same_item_again(terms, mentions, before):
        mentions = mentions[:1]  # "I meant Mao's seal": the owner is what is corrected
    owner = _owned_new_thing(terms, mentions)
    if owner:
        mentions = mentions[1:]  # "no wait, Sun's scissors": the scissors, Sun's
    # a name several people may have is kept as said: the reader asks whom it means later
    if len(mentions) != 1 or (len(mentions[0].ids) != 1 and mentions[0].kind != "person"):
        return text, []
    new = mentions[0]
    if new.kind == "person" and not new.possessive and _subject_of_news(tokens, new.end):
        return text, []
    names = spellings(terms, new.kind, before)
    if rejected:
        said_no = " ".join(t.text for t in rejected)
        names = (spellings(terms, new.kind, said_no) & names) or names
    if not names:
        return text, []
    old = _last_said(names, before)
    if old is None:
        return text, []
    said = new.text.replace("’", "'").removesuffix("'s")
    if alone:
        # "robin" said alone: written as the person's name, so no later stage takes the
        # lower-case word for the ordinary one
        said = terms.office.person(new.ids[0]).name
    if new.kind == "item":
        said = terms.office.item_type(new.ids[0]).name + source
    between = before[old.end() :]
    head = before[: old.start()]
    if owner:
        # "can i borrow a pen? no wait, Sun's scissors": whose the new thing is replaces the
        # old thing's article or owner too (before, anyone's scissors were fetched)
        head = _DETERMINER_AT_END.sub("", head)
        said = f"{owner}'s {said}"
    if new.kind == "person" and not new.possessive:
        same = old.group(0).lower() in {n.lower() for n in spellings(terms, "person", fix)}
        if same and _turned_from_receiver(tokens, new, head):
            # "bring Zhang a stapler - sorry, I mean one from Zhang": the person named as the
            # receiver, with no "to" to turn, is who it comes from; it goes to the speaker
            fixed = f"{head}me{between.rstrip(_TRAILING)} from {said}{rest}"
            meaning = f"{REPLACED}{said}, as whom it comes from"
            return fixed, [Evidence(words=text[match.start() :].strip(), meaning=meaning)]
        head = _role_said_again(tokens, new, head)
    if new.kind == "person" and new.possessive:
        between = _owner_said_again(terms, between, said)
    fixed = head + said + between + rest
    return fixed, [Evidence(words=text[match.start() :].strip(), meaning=f"{REPLACED}{said}")]


# The words before a place a correction says alone ("no wait, *to the* kitchen")
_PLACE_OPENERS = frozenset({"to", "at", "in", "into", "the"})
_PLACE_KINDS = ("place", "facility")


def _place_corrected(
    terms: Terms, tokens: Sequence[Token], before: str, rest: str
) -> tuple[str, str] | None:
    """ "take my jug to the microwave, no wait, the kitchen": a correction that is one place
    or facility alone replaces the last place or facility of the request it corrects (where
    the thing goes, or the machine that works on it); what else the request said stands.
    The text so corrected and the place's words; None where the correction names more than
    a place, or the request named none."""
    mentions = [m for m in terms.lex.scan(list(tokens)) if m.kind != "word"]
    if len(mentions) != 1 or mentions[0].kind not in _PLACE_KINDS:
        return None
    new = mentions[0]
    if new.end != len(tokens) or any(t.word not in _PLACE_OPENERS for t in tokens[: new.start]):
        return None
    said = [m for m in terms.lex.scan(terms.lex.tokens(before)) if m.kind in _PLACE_KINDS]
    if not said:
        return None
    old = re.escape(said[-1].text).replace(r"\ ", r"\s+")
    spots = list(re.finditer(rf"\b{old}\b", before, re.IGNORECASE))
    if not spots:
        return None
    spot = spots[-1]
    return before[: spot.start()] + new.text + before[spot.end() :] + rest, new.text


# What opens the old thing's noun phrase, said right before it ("a", "the", "my", "Zhang's")
_DETERMINER_AT_END = re.compile(
    r"\b(?:a|an|the|some|any|my|your|his|her|their|our|[^\W\d_]+['’]s)\s*$", re.IGNORECASE
)


def _owned_new_thing(terms: Terms, mentions: list[Mention]) -> str:
    """The one colleague's name where a correction says a thing with its owner ("no wait, Sun's
    scissors": Sun Li); "" otherwise (one mention, or the owner is all that is corrected)."""
    if len(mentions) != 2:
        return ""
    person, item = mentions
    if person.kind != "person" or not person.possessive or len(person.ids) != 1:
        return ""
    if item.kind != "item" or item.start != person.end:
        return ""
    return terms.office.person(person.ids[0]).name


def _last_said(names: set[str], text: str, *, with_s: bool = False) -> re.Match[str] | None:
    """Where one of ``names`` (a person's spellings) is said last in ``text``, the longest
    spelling first; ``with_s``: a possessive "'s" after it is part of the match (group "s")."""
    pattern = "|".join(re.escape(n) for n in sorted(names, key=len, reverse=True))
    tail = r"(?P<s>['’]s\b)?" if with_s else r"\b"
    spots = list(re.finditer(rf"\b(?:{pattern}){tail}", text, re.IGNORECASE))
    if not spots:
        return None
    # "Tom Hughes's": a given name and a surname said one after the other are one name, all
    # of it corrected (only "Hughes's" replaced left "Tom", whom the reader then asked about)
    start = spots[-1].start()
    for spot in reversed(spots[:-1]):
        if spot.end() > start or text[spot.end() : start].strip() or spot.group(0).endswith("s"):
            break
        start = spot.start()
    if start == spots[-1].start():
        return spots[-1]
    said = re.escape(text[start : spots[-1].start()])
    return re.compile(rf"{said}(?:{pattern}){tail}", re.IGNORECASE).match(text, start)


def _to_speaker(
    terms: Terms, text: str, start: int, before: str, refused: Sequence[Token], rest: str
) -> tuple[str, list[Evidence]]:
    """ "bring me Lee's stapler. sorry, not Lee's, mine": the person refused is replaced by
    the speaker, as owner ("my") where they were said with "'s", else as "me"."""
    names = spellings(terms, "person", " ".join(t.text for t in refused))
    names &= spellings(terms, "person", before)
    if not names:
        return text, []
    old = _last_said(names, before, with_s=True)
    if old is None:
        return text, []
    said = "my" if old.group("s") else "me"
    fixed = before[: old.start()] + said + before[old.end() :] + rest
    return fixed, [Evidence(words=text[start:].strip(), meaning=f"{REPLACED}the speaker")]


def _source_kept(tokens: list[Token], fix: str) -> tuple[list[Token], str]:
    """ "a snack from the vending machine": a correction too long to be one thing, whose
    thing is followed by where it comes from, is that thing (the first tokens) and the
    words of where, said after the thing it replaces (" from the vending machine")."""
    if len(tokens) <= 5:
        return tokens, ""
    words = [t.word for t in tokens]
    for k in range(1, 6):
        if any(tuple(words[k : k + len(s)]) == s for s in _SOURCES):
            said = re.search(rf"\b{re.escape(tokens[k].text)}\b", fix, re.IGNORECASE)
            if said is not None:
                return tokens[:k], " " + fix[said.start() :].strip()
    return tokens, ""


# The words that say which way a thing goes with a person: to them, or from them.
_ROLE_WORDS = frozenset({"to", "from", "for"})
_ROLE_BEFORE = re.compile(r"\b(to|from|for)(\s+)$", re.IGNORECASE)


def _role_said_again(tokens: Sequence[Token], new: Mention, head: str) -> str:
    """ "get a stapler to Zhang - sorry, I mean one FROM Zhang": a correction that says the
    person with another "to"/"from" than before turns the way the thing goes, not only who:
    the old word before the name is replaced with the new one."""
    if new.start == 0 or tokens[new.start - 1].word not in _ROLE_WORDS:
        return head
    said = _ROLE_BEFORE.search(head)
    if said is None or said.group(1).lower() == tokens[new.start - 1].word:
        return head
    return head[: said.start()] + tokens[new.start - 1].word + said.group(2)


def _turned_from_receiver(tokens: Sequence[Token], new: Mention, head: str) -> bool:
    """Whether a correction says the person "from" whom the thing comes where the request
    named them, with no "to"/"from"/"for" before, as its receiver ("bring *Zhang* a
    stapler"): only a name right after the request's first verb."""
    if new.start == 0 or tokens[new.start - 1].word != "from":
        return False
    if _ROLE_BEFORE.search(head):
        return False  # "to Zhang": turned by _role_said_again
    words = re.findall(r"[^\W\d_]+", head.lower())
    return bool(words) and words[-1] in _GIVING_VERBS


# a verb whose first object is who receives ("bring *Zhang* a stapler", "get her one")
_GIVING_VERBS = frozenset({"bring", "get", "take", "fetch", "grab", "hand", "give", "pass"})


_OWNER_PRONOUN = re.compile(r"\b(?:his|her|their)\s+", re.IGNORECASE)


def _owner_said_again(terms: Terms, between: str, said: str) -> str:
    """ "ask Olive to lend me her calculator? Sorry, I meant Anne-Marie's": a possessive
    correction says whose the thing is, so the owner's pronoun after the name it replaces
    ("her calculator") is the new owner's too, whatever is said beside the correction
    ("..., Olive took hers home" names the old owner again, and must not take it back)."""
    for pronoun in _OWNER_PRONOUN.finditer(between):
        tokens = terms.lex.tokens(between[pronoun.end() :])
        head = [m for m in terms.lex.scan(tokens[:4]) if m.start <= 1]
        if head and head[0].kind == "item":
            return between[: pronoun.start()] + f"{said}'s " + between[pronoun.end() :]
    return between


# Words after a name that make it the subject of what follows ("sorry, Otto has it")
_SUBJECT_AFTER = frozenset({"has", "have", "is", "was", "will", "can", "could", "might", "s"})


def _subject_of_news(tokens: Sequence[Token], end: int) -> bool:
    """ "take my file to Sam. sorry, Otto has the other one": a person named before a verb
    after "sorry" is the subject of news, not the receiver corrected (the consent guard reads
    it so too)."""
    if end >= len(tokens):
        return False
    after = tokens[end].word
    return after in _SUBJECT_AFTER or language.is_finite_verb(after)


def _name_said_alone(terms: Terms, tokens: Sequence[Token]) -> list[Mention]:
    """ "to sam. sorry not sam, robin": a correction that is one name word of one colleague
    names them, though the word is also an ordinary one (a robin): a correction replaces what
    was just said, and a bare bird or month is nothing it could replace a person or an item
    with."""
    if len(tokens) != 1:
        return []
    ids = terms.lex.name_words.get(tokens[0].word, set())
    if len(ids) != 1:
        return []
    token = tokens[0]
    return [Mention("person", 0, 1, tuple(ids), token.possessive, token.text)]


# Words of correcting said again after a correction's mark ("no wait *sorry*, a pen")
_MORE_MARKS = re.compile(r"^(?:(?:sorry|oops|actually|wait)\b[,!.]?\s*)+", re.IGNORECASE)


def _last_of_chain(after: str) -> str:
    """ "heat... sorry, STEAM, nope, I mean get Zoë's straighteners": a correction that is
    corrected again at once (its few words, then another correction) says nothing that
    stands; the last correction of the chain is what the first one corrects to."""
    while True:
        fix = re.split(r"[,.!?;\n]|\s[-–—]+\s", after, maxsplit=1)[0]
        again = _CORRECTION.match(after, len(fix))
        if not fix.strip() or len(fix.split()) > _CHAINED_WORDS or again is None:
            return after
        after = after[again.end() :]


# The most words of a correction that is itself corrected at once ("STEAM", "the blue one").
_CHAINED_WORDS = 4


# The words a correction's own request says the thing of the request it replaces by: its
# first "it" where it ends or goes on to where, for whom or a second verb ("scan *it* and give
# it to Joel": the first is the thing, the second is what scanning it made)
_KEPT_THING = re.compile(
    r"\b(it|them|that)\b(?=\s*(?:$|[,.!?;]|\s[-–—]|\s+(?:to|for|over|back|instead|please|pls|"
    r"plz|again|now|thanks|and|then)\b))",
    re.IGNORECASE,
)


# "it's", "it is", "that's": the thing just said, described
_IT_IS = (("it", "is"), ("that", "is"), ("its",), ("thats",))


def _what_it_is(terms: Terms, tokens: Sequence[Token], rest: str) -> bool:
    """Whether a correction's first clause only says what the thing is ("it's the paper
    one", "it is a paper copy"), naming nobody, and a request of its own follows it after a
    comma."""
    words = [t.word for t in tokens]
    if tokens and tokens[0].word in ("it", "that") and tokens[0].possessive:
        words = [tokens[0].word, "is", *words[1:]]  # "it's": "it is"
    if not any(tuple(words[: len(w)]) == w for w in _IT_IS) or not rest.startswith(","):
        return False
    if any(m.kind == "person" for m in terms.lex.scan(list(tokens))):
        return False  # "it's Gao's, bring me that one": whose it is corrects the owner
    nxt = re.split(r"[,.!?;\n]|\s[-–—]+\s", rest[1:], maxsplit=1)[0]
    return opens_request(terms, terms.lex.tokens(nxt))


# who a reason that rules the one said out is told of ("*she*'s using it", "*it*'s broken")
_REASON_SUBJECTS = frozenset({"he", "she", "they", "it", "that", "its", "thats", "hes", "shes"})
# a subject with its "is" run in, as typed in chat ("hes out", "shes busy", "its broken")
_IS_TYPED_IN = frozenset({"hes", "shes", "its", "thats"})
# what opens a choice said after the reason: "*try* Zhang's", "Zhang's *then*"
_CHOICE_WORDS = frozenset({"try", "then", "instead", "ask", "get", "use", "maybe", "so"})


def _why_ruled_out(terms: Terms, tokens: Sequence[Token]) -> bool:
    """Whether a correction's first clause only tells why the one just said will not do: a
    subject told of ("she", "he", "it" or a colleague) and a verb after it ("she's using
    it", "he needs it today", "it's broken"), naming no thing of the office."""
    if len(tokens) < 2 or opens_request(terms, tokens):
        return False
    mentions = terms.lex.scan(list(tokens))
    if any(
        m.kind == "item"
        or (m.kind in ("facility", "place") and not _where_at(tokens, m.start))
        or (m.kind == "person" and m.start > 0)
        for m in mentions
    ):
        return False
    first = tokens[0]
    if first.word not in _REASON_SUBJECTS and not (mentions and mentions[0].kind == "person"):
        return False
    words = [t.word for t in tokens[1:]]
    # "hes at the area meeting": the subject's "is" typed into it, without its apostrophe
    return (
        first.possessive
        or first.word in _IS_TYPED_IN
        or any(language.is_finite_verb(w) or language.is_present_participle(w) for w in words)
    )


# "she's using it *on* the vault shelves": where the one said is busy, no thing asked for
_WHERE = frozenset({"on", "in", "at", "by", "near", "inside", "over", "under", "down", "up"})


def _where_at(tokens: Sequence[Token], at: int) -> bool:
    """Whether the place or facility said at ``at`` follows a preposition of where (its
    article between): where the reason's subject is busy, not a thing of the request."""
    k = at - 1
    while k >= 0 and tokens[k].word in DETERMINERS:
        k -= 1
    return k >= 0 and tokens[k].word in _WHERE


def _choice_after_reason(terms: Terms, rest: str) -> tuple[str, str] | None:
    """The clause right after a reason (``rest`` opens with its pause or stop) and what
    follows it, where that clause names one colleague's thing or one thing of the office
    and asks nothing of its own ("Zhang's then", "try Zhang's", "a pencil instead")."""
    lead = re.match(r"\s*(?:[,.;!?…]+|[-–—]+)\s*", rest)
    if lead is None or not lead.group(0).strip():
        return None
    after = rest[lead.end() :]
    fix = re.split(r"[,.!?;\n]|\s[-–—]+\s", after, maxsplit=1)[0]
    tokens = terms.lex.tokens(fix)
    if not tokens or len(tokens) > 4 or opens_request(terms, tokens):
        return None
    mentions = [m for m in terms.lex.scan(tokens) if m.kind in ("person", "item")]
    others = [
        t.word
        for n, t in enumerate(tokens)
        if not any(m.start <= n < m.end for m in mentions) and t.word not in _CHOICE_WORDS
    ]
    if len(mentions) != 1 or others:
        return None
    chose = any(t.word in _CHOICE_WORDS for t in tokens)
    if mentions[0].kind == "person" and not mentions[0].possessive and not chose:
        # "..., she's using it. Zhang needs one too": news, no choice; "ask Dolores
        # instead", "try Zhang then": the colleague chosen to do it
        return None
    return fix, after[len(fix) :]


def thing_kept(terms: Terms, withdrawn: str, tokens: Sequence[Token], after: str) -> str:
    """ "take my mug to the kitchenette - no wait, give it to Fang": a correction that says
    a request of its own with "it"/"them"/"that" for its thing, and names no thing itself,
    keeps the thing (and its owner) of the request it replaces; only where and to whom it
    goes is new. A withdrawn request naming no one thing leaves "it" as said."""
    if any(m.kind == "item" for m in terms.lex.scan(list(tokens))):
        return after  # "bring me a pen - no wait, bring me a pencil": the thing replaced
    said = terms.lex.tokens(withdrawn)
    mentions = terms.lex.scan(said)
    items = [n for n, m in enumerate(mentions) if m.kind == "item"]
    if len(items) != 1:
        return after
    n = items[0]
    item = mentions[n]
    start = item.start
    owner = mentions[n - 1] if n else None
    if owner is not None and owner.kind in ("self", "person") and owner.possessive:
        if item.start - owner.end <= 2:
            start = owner.start
    phrase = " ".join(t.text for t in said[start : item.end])
    if start == item.start:
        phrase = f"the {phrase}"
    found = _KEPT_THING.search(after)
    if found is None:
        return after
    return after[: found.start()] + phrase + after[found.end() :]


def opens_request(terms: Terms, tokens: Sequence[Token]) -> bool:
    """Whether a correction's words open with a request verb of their own ("just print my
    draft", "please bind my plan instead"), not a person or an item alone."""
    words = [t.word for t in tokens if t.word not in _FILLERS]
    opens = bool(words) and (
        words[0] in terms.lex.cue_words or words[0] in terms.lex.operation_words
    )
    return opens and terms.acts.request(words)


# The words that join a later part of a request to the one before it ("print it *and* take it")
_PART_JOINS = re.compile(r"(?:,|\band\b|\bthen\b)\s*(?:then\s+)?$", re.IGNORECASE)


def _part_said_again(tokens: Sequence[Token], before: str, cut: int) -> int:
    """Where the part a correction says again starts, in the request it breaks off: the last
    place that request's later part (after "and", "then" or a comma) opens with the
    correction's own verb, or a verb of handing a thing on where the correction's is one too
    ("take it to Ivo" / "I meant bring it to Amber"); ``cut`` (the whole request) otherwise."""
    start = cut
    words = [t.word for t in tokens if t.word not in _FILLERS]
    if not words:
        return start
    verb = words[0]
    same = {verb} | (_GIVING_VERBS if verb in _GIVING_VERBS else set())
    found = start
    for m in re.finditer(r"[^\W\d_]+", before[start:]):
        at = start + m.start()
        if at == start or m.group(0).lower() not in same:
            continue
        if _PART_JOINS.search(before[start:at].rstrip()):
            found = at
    return found


def _same_item_again(terms: Terms, mentions: list[Mention], before: str) -> bool:
    """ "bring me Ann's torch... sorry, I meant Dev's torch": a person's possessive and the
    item already asked for, said again with the new owner."""
    whose, item = mentions
    if whose.kind != "person" or not whose.possessive or item.kind != "item":
        return False
    said = {i for m in terms.lex.scan(terms.lex.tokens(before)) if m.kind == "item" for i in m.ids}
    return set(item.ids) <= said


def spellings(terms: Terms, kind: str, text: str) -> set[str]:
    """How the people (or items) ``text`` names are written there."""
    tokens = terms.lex.tokens(text)
    ids = {i for m in terms.lex.scan(tokens) if m.kind == kind for i in m.ids}
    if kind == "person":
        people = [terms.office.person(i) for i in ids]
        return {n for p in people for n in (p.name, *p.aliases, *p.name.split()) if n}
    return {
        n
        for i in ids
        for t in [terms.office.item_type(i)]
        for n in (t.name, *t.synonyms, language.plural(t.name))
    }
