"""A rejected alternative with its replacement ("sorry not a ruler, i meant a tape measure -
can i borrow Teodor's?", "bring me Maren's folder - not the blue folder, the red one"): the
thing said after "not X," is the one meant, and it takes the place of X (or of the thing the
request left unsaid, "Teodor's") in the request, before the pieces are judged. "the red one"
is the rejected thing's noun with the new word ("the red folder"). Only where both name an
item of the office and they differ; anything else is left as written (the correction and
exclusion rules read it).

The same holds for whose it is: "not Wang's stapler, Zhang's - bring it over please" means
Zhang's stapler; the new owner's name takes the old one's place, or "it" in the request where
the request does not name the item again. The new owner is asked before it moves, as ever."""

from __future__ import annotations

import re

from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import language
from assistantx.core.task_schema import Evidence

_BREAK = r"[,;.!?]|\s[-–—]+"
_REJECTED = re.compile(
    rf"(?P<lead>^|(?:{_BREAK})\s*)"
    r"(?:(?:sorry|oops|oh|no|wait|actually)[,!.]?\s+)*"
    r"not\s+(?P<x>[^,;.!?–—]+?)\s*(?:[,;]|\s[-–—]+)\s*"
    r"(?:(?:but|sorry|rather|no)[,]?\s+)?"
    r"(?:i\s+(?:meant|mean|want|wanted|need|needed)\s+)?"
    rf"(?P<y>[^,;.!?–—]+?)\s*(?P<end>{_BREAK}|$)",
    re.IGNORECASE,
)
_ONE = re.compile(r"\bones?\s*$", re.IGNORECASE)
# A name's possessive with nothing after it ("can i borrow Teodor's?"): the thing left unsaid.
_BARE_POSSESSIVE = r"['’]s(?=\s*(?:[,;.!?]|\s[-–—]|$))"


def rejected_alternative(terms: Terms, text: str) -> tuple[str, list[Evidence]]:
    """The text with "not X, Y" taken out and Y put where X (or the unsaid thing) was."""
    for match in _REJECTED.finditer(text):
        x = match.group("x")
        x_item = _one_item(terms, x)
        if x_item is None:
            continue
        y = match.group("y")
        if _ONE.search(y):  # "the red one": the rejected thing's noun
            y = _ONE.sub(language.words(x)[-1], y)
        y_item = _one_item(terms, y)
        if y_item is None or y_item == x_item:
            swapped = _owner_swapped(terms, text, match, x, y, x_item)
            if swapped is not None:
                return swapped
            continue
        # the rejection and its replacement taken out, with the break before and after it
        rest = f"{text[: match.start()]} {text[match.end() :]}".strip(" ,;–—-")
        name = terms.office.item_type(y_item).name
        fixed = _put_in(terms, rest, x_item, language.words(x)[-1], name)
        if fixed is None:
            continue
        said = text[match.start() : match.end()].strip(" ,;.!?-–—")
        return fixed, [Evidence(words=said, meaning=f"means {name}")]
    return text, []


_IT = re.compile(r"\b(?:it|that|this|them)\b", re.IGNORECASE)


def _owner_of(terms: Terms, phrase: str) -> str | None:
    """The one person whose thing a phrase names ("Wang's stapler", "Zhang's", "zhang's one")."""
    lexed = terms.lex.read(phrase)
    owners = [m for m in lexed.mentions if m.kind == "person" and m.possessive]
    others = [m for m in lexed.mentions if m.kind == "person" and not m.possessive]
    if len(owners) != 1 or others or len(owners[0].ids) != 1:
        return None
    return owners[0].ids[0]


def _owner_swapped(
    terms: Terms, text: str, match: re.Match[str], x: str, y: str, item: str
) -> tuple[str, list[Evidence]] | None:
    """ "not Wang's stapler, Zhang's": the same item of another owner, put in the request."""
    old, new = _owner_of(terms, x), _owner_of(terms, y)
    y_item = _one_item(terms, y)
    if old is None or new is None or old == new or y_item not in (None, item):
        return None
    leftover = [w for w in language.words(y) if w not in ("one", "the", "s")]
    if y_item is None and len(leftover) > len(language.words(terms.office.person(new).name)):
        return None  # "not Wang's stapler, Zhang wants it": no replacement said
    rest = f"{text[: match.start()]} {text[match.end() :]}".strip(" ,;–—-")
    t = terms.office.item_type(item)
    thing = f"{terms.office.person(new).name}'s {t.name}"
    if _one_item(terms, rest) == item:
        return None  # the request names the item again: the owner rules read it as said
    spots = list(_IT.finditer(rest))
    if len(spots) != 1:
        return None
    fixed = rest[: spots[0].start()] + thing + rest[spots[0].end() :]
    said = text[match.start() : match.end()].strip(" ,;.!?-–—")
    return fixed, [Evidence(words=said, meaning=f"means {thing}")]


def _one_item(terms: Terms, phrase: str) -> str | None:
    mentions = [m for m in terms.lex.scan(terms.lex.tokens(phrase)) if m.kind == "item"]
    if len(mentions) != 1 or len(mentions[0].ids) != 1:
        return None
    return mentions[0].ids[0]


def _put_in(terms: Terms, rest: str, rejected: str, head: str, name: str) -> str | None:
    """The request with the replacement where the rejected thing, its bare noun, or the
    thing a bare possessive leaves unsaid was; None where it names none of them."""
    t = terms.office.item_type(rejected)
    spellings = sorted({t.name, *t.synonyms, language.plural(t.name)}, key=len, reverse=True)
    for said in (*spellings, head):
        spots = list(re.finditer(rf"\b{re.escape(said)}\b", rest, re.IGNORECASE))
        if spots:
            at = spots[-1]
            return rest[: at.start()] + name + rest[at.end() :]
    bare = list(re.finditer(_BARE_POSSESSIVE, rest))
    if len(bare) == 1 and not terms.named(terms.lex.read(rest), "item"):
        at = bare[0]
        return f"{rest[: at.end()]} {name}{rest[at.end() :]}"
    return None
