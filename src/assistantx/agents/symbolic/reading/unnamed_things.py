"""A thing an errand's verb takes that the office has no name for: "take my lamp to Rose, and
bring me Grace's highlighter" in an office with no lamp. The frames read the part they can (the
highlighter) and the part with the unknown noun made no task, so it vanished and "Done"
was reported for the rest (or, worse, the rest took that part's recipient: "bring me Grace's
highlighter and take my lamp to Rose" handed the highlighter to Rose).

The rule is about English and the office's own names: an errand's verb (a task word of the
lexicon), then perhaps whom it is for ("me", a colleague), then a possessive ("my", "Grace's")
and a plain noun no name of the office reads (after a modifier or two) is a thing the request
asks to move. No task can carry it, so the part is asked about before anything moves
(``parts.unread_part``), quoting the phrase. A noun that modifies an office's item ("my desk
lamp" where "lamp" is an item's name) is that item; a statement or reason beside a request
("- mine's broken") has no errand's verb before it and is never asked about.
"""

from __future__ import annotations

from collections.abc import Collection, Sequence

from assistantx.agents.symbolic.reading.categories import category_named
from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.tokens import Token
from assistantx.core import english, language

_COMMON = english.words("common")
_VAGUE = english.words("vague_things")
_POINTING_BACK = english.words("pointing_back")  # "bring me the original back"
_MODIFIERS = 2  # plain words before the noun ("my old desk lamp")
# whom the thing is for, said between the verb and the thing ("bring *me* Grace's ...")
_FOR_WHOM = frozenset({"self", "person"})
# the task words that move a thing to someone ("take", "bring", "borrow"), less the ones that
# only say a wish ("I'd like my ...")
_GIVE = "give"
_WISHES = frozenset({"like", "love", "need", "needs", "want", "wants"})
# the articles before a thing the lexicon leaves without a mention ("take *a* lamp to Rose")
_ARTICLES = frozenset({"a", "an", "the", "some", "this", "that"})
# The joining word of a second thing the same verb takes ("a stapler *and* the projector").
_AND = "and"
_TO = "to"
_FOR = "for"
# The words after a joined thing that end its clause ("and the projector *please*").
# The word that says where a thing comes from, and what it names: "from the cupboard".
_FROM = "from"
_SOURCES = frozenset({"facility", "place", "person"})
# A thing said: its phrase, whose it is (None: nobody's), and the token after it.
Said = tuple[str, str | None, int]
# the nouns of a unit or a portion of a thing ("a *sheet* of paper", "a *box* of gizmos")
_UNITS = english.words("unit_nouns") | english.words("portion_words")
_OF = "of"
_CLAUSE_ENDS = frozenset({"please", "pls", "too", "as", "and", "then", "to", "for", "asap", "now"})


def unnamed_thing(
    mentions: Sequence[Mention], tokens: Sequence[Token], owners: Collection[str | None], me: str
) -> str | None:
    """The phrase of the first thing an errand's verb takes that names nothing of the office
    ("my lamp", "a lamp"), as said; None when there is none. ``owners``: whose things the
    tasks read carry where no name of the thing was said (None: nobody's); a phrase of an owner
    among them was read as their thing by another stage ("take my lease to Ines to be
    stamped": the one paper of mine a seal takes), not left out."""
    for n, verb in enumerate(mentions):
        if verb.kind != "cue" or _GIVE not in verb.ids:
            continue
        # "I need a break": a wish names no errand, unless it says where the thing is to
        # come from ("I need a gizmo pad from the cupboard"): then it asks for a fetch
        wish = tokens[verb.start].word in _WISHES
        k = n + 1
        if _for_whom_first(mentions, k, verb.end):
            k += 2  # "bring for me ...": whom it is for, said before the thing
        elif _next(mentions, k, verb.end) and mentions[k].kind in _FOR_WHOM:
            if not mentions[k].possessive:
                k += 1  # "bring me ...", "give Rose ..."
        said = _thing_said(mentions, tokens, k, mentions[k - 1].end, me)
        if said is None:
            said = _joined_thing(mentions, tokens, k, mentions[k - 1].end, me)
        if said is None or said[1] in owners:
            continue
        if wish and not _source_at(mentions, tokens, said[2]):
            continue
        return said[0]
    return _joined_without_verb(mentions, tokens, owners, me)


def _joined_without_verb(
    mentions: Sequence[Mention], tokens: Sequence[Token], owners: Collection[str | None], me: str
) -> str | None:
    """ "a tea and a biscuit please", "can I have a ruler and a gizmo": a request said with no
    errand's verb still joins its things by "and"; the one no name of the office reads is a
    thing asked for (the tea was made and the biscuit never mentioned)."""
    for n, m in enumerate(mentions):
        if m.kind != "item" or any(x.kind == "cue" and x.end <= m.start for x in mentions):
            continue
        said = _joined_thing(mentions, tokens, n, m.start, me)
        if said is not None and said[1] not in owners:
            return said[0]
    return None


def _for_whom_first(mentions: Sequence[Mention], k: int, end: int) -> bool:
    """Whether "for" and whom the thing is for ("me", a colleague) follow the verb straight
    on ("bring *for me* a tea"), before the thing."""
    if not (_next(mentions, k, end) and _next(mentions, k + 1, mentions[k].end)):
        return False
    said, whom = mentions[k], mentions[k + 1]
    return (
        said.kind == "word"
        and said.ids[:1] == (_FOR,)
        and whom.kind in _FOR_WHOM
        and not whom.possessive
    )


def _source_at(mentions: Sequence[Mention], tokens: Sequence[Token], at: int) -> bool:
    """Whether "from" and one of the office's own places, facilities or people stand at the
    token ``at`` ("... *from the cupboard*", "... from Tomas"): where a thing is fetched from,
    which ends the noun phrase of the thing before it."""
    if at >= len(tokens) or tokens[at].word != _FROM or tokens[at].after_pause:
        return False
    k = at + 1
    while k < len(tokens) and tokens[k].word in _ARTICLES:
        k += 1
    return any(m.start == k and m.kind in _SOURCES for m in mentions)


def _joined_thing(
    mentions: Sequence[Mention], tokens: Sequence[Token], k: int, end: int, me: str
) -> Said | None:
    """A thing no name of the office reads joined by "and" to the verb's known object ("bring
    me a stapler *and the projector*"): a noun with no verb of its own shares the verb before
    it, so it is a thing the request asks to move, never a part to drop. Only a phrase that
    ends its clause ("and the projector", "and a lamp please") is such a noun: "and the
    meeting starts at 3" is a clause of its own."""
    while True:
        k, end = _known_object(mentions, tokens, k, end)
        if end < 0 or not _next(mentions, k, end) or tokens[end].word != _AND:
            return None
        k, end = k + 1, mentions[k].end
        said = _thing_said(mentions, tokens, k, end, me, joined=True)
        if said is None:
            continue  # "a stapler and scissors": known too, or none; on to what follows
        last = max(_phrase_end(tokens, end), said[2])
        if last < len(tokens) and not (
            tokens[last].after_pause
            or tokens[last].opens
            or tokens[last].word in _CLAUSE_ENDS
            or _source_at(mentions, tokens, last)  # "and a flux pad from the cupboard"
        ):
            return None
        return said


def _known_object(
    mentions: Sequence[Mention], tokens: Sequence[Token], k: int, end: int
) -> tuple[int, int]:
    """The mention index after the object read at the token ``end`` ("a stapler", "my
    stapler", "Lee's pen"), and the token after it; (k, -1) where no item is read there."""
    if _next(mentions, k, end) and mentions[k].possessive and mentions[k].kind in _FOR_WHOM:
        k, end = k + 1, mentions[k].end
    elif end < len(tokens) and tokens[end].word in _ARTICLES:
        if _next(mentions, k, end):
            k += 1  # "some" is a word of the lexicon's, "a" none
        end += 1
    if not (_next(mentions, k, end) and mentions[k].kind == "item"):
        return k, -1
    k, end = k + 1, mentions[k].end
    if _next(mentions, k, end) and tokens[end].word == _TO and _next(mentions, k + 1, end + 1):
        if mentions[k + 1].kind in _FOR_WHOM:
            # "my stapler to Lee and the projector to Wang": the first thing's recipient
            k, end = k + 2, mentions[k + 1].end
    if _next(mentions, k, end) and _source_at(mentions, tokens, end):
        # "a stapler from Sun Li and a lamp ...": where the first thing comes from
        source = next(n for n in range(k + 1, len(mentions)) if mentions[n].kind in _SOURCES)
        k, end = source + 1, mentions[source].end
    return k, end


def _phrase_end(tokens: Sequence[Token], start: int) -> int:
    """The token after the noun phrase from ``start`` (its opener, then plain words)."""
    at = start + 1
    while (
        at < len(tokens)
        and not tokens[at].after_pause
        and tokens[at].word not in _COMMON
        and tokens[at].word not in _CLAUSE_ENDS
        and at - start <= 1 + _MODIFIERS
    ):
        at += 1
    return at


def _next(mentions: Sequence[Mention], k: int, end: int) -> bool:
    """Whether ``mentions[k]`` follows straight on from the token ``end``."""
    return k < len(mentions) and mentions[k].start == end


def _thing_said(
    mentions: Sequence[Mention],
    tokens: Sequence[Token],
    k: int,
    end: int,
    me: str,
    *,
    joined: bool = False,
) -> Said | None:
    """The phrase "my/Grace's/a/the [modifier] noun" from the token ``end`` (``mentions[k]``
    on) whose noun no name of the office reads, whose it says (None: nobody's), and the token
    after it."""
    if _next(mentions, k, end) and mentions[k].possessive and mentions[k].kind in _FOR_WHOM:
        opener = mentions[k]
        whose = me if opener.kind == "self" else opener.ids[0] if len(opener.ids) == 1 else ""
        start, k = opener.start, k + 1
    elif end < len(tokens) and tokens[end].word in _ARTICLES:
        whose, start = None, end  # "take a lamp to Rose": the article is no mention
        if _next(mentions, k, end):
            k += 1  # "get me some gizmo": "some" is a word of the lexicon's
    else:
        return None
    run: list[Mention] = []
    at = start + 1
    for m in mentions[k:]:
        if m.start != at or tokens[m.start].opens or tokens[m.start].after_pause:
            break
        if m.kind != "word":
            return None  # "my desk lamp" where the lamp is the office's: that item
        word = m.ids[0] if m.ids else tokens[m.start].word
        if word in _COMMON or word in _VAGUE or word in _POINTING_BACK or not word.isalpha():
            break
        run.append(m)
        at = m.end
    if not run or len(run) > 1 + _MODIFIERS:
        return None  # nothing said, or too long a phrase to be one thing's name
    head = run[-1]
    noun = tokens[head.start].word
    # a word no dictionary knows, joined by "and" to a thing asked for ("and some
    # paperclips"), is a thing's name all the same; alone after the verb it may be a file's
    # form ("send Omar the pdf of my invoice")
    unknown = joined and not language.lemmas(noun)
    if not (language.is_noun(noun) or unknown) or tokens[head.start].corrected or whose == "":
        return None
    named = " ".join(tokens[m.start].word for m in run)
    if category_named(named) is not None or category_named(noun) is not None:
        return None  # "a drink", "a hot drink": a kind of thing, asked or offered by its stage
    end = head.end
    if noun in _UNITS and end < len(tokens) and tokens[end].word == _OF:
        # "a sheet of paper", "a box of gizmos": the thing is what the unit is of, and the
        # phrase goes on to it (before, it stopped at "of" and the thing was dropped unsaid)
        end = _unit_of(mentions, tokens, end + 1)
        if end < 0:
            return None  # "a box of staples": of the office's own thing, read as that
    return " ".join(t.text for t in tokens[start:end]), whose, end


def _unit_of(mentions: Sequence[Mention], tokens: Sequence[Token], at: int) -> int:
    """The token after the plain noun phrase that starts at ``at`` (after a unit's "of"):
    -1 where it names a thing of the office or no noun."""
    end = at
    for m in mentions:
        if m.end <= at:
            continue
        if m.start != end or tokens[m.start].after_pause or end - at > _MODIFIERS:
            break
        if m.kind != "word":
            return -1
        word = m.ids[0] if m.ids else tokens[m.start].word
        if word in _COMMON or not word.isalpha():
            break
        end = m.end
    if end == at or not language.is_noun(tokens[end - 1].word):
        return -1
    return end
