"""A colleague's want said with a helping verb: "Zhang would like a stapler", "Zhang'd like a
stapler", "Zhang could use a stapler", "Zhang could do with some tape" (``modal_wants``).

Said of a name, each is that person's want, read as "Zhang needs a stapler": a third
person's need, restated and asked before anything moves ("Shall I bring a stapler to Zhang
Wei?"). Left as said, "would like" read as the speaker's own wish (a stapler fetched for the
speaker), "Zhang'd" was taken for an unknown name, and "could use" for request wording (the
stapler brought at once). The want is read only before what is wanted (an article or a
possessive): "Zhang would like you to print it" and "Zhang would like to know" are read as
before. Asked of a name ("would Zhang like a stapler?") it is the same want put as a question:
read as "Zhang needs a stapler?", restated and asked, never the speaker's borrowing of
Zhang's stapler ("would you like ...", naming nobody, is left as said)."""

from __future__ import annotations

import re
from collections.abc import Callable

from assistantx.agents.symbolic.reading.reported_request import named_tail, phrase_alternatives
from assistantx.core import english

# what is wanted opens with a determiner or a possessive ("a stapler", "some of my tape")
_WANTED = r"(?:a|an|the|some|one|another|any|more|his|her|their|my|your|our)\b"
# "Zhang'd like": the "'d" after a name is "would" (the speaker's "I'd" is left as said)
_WOULD = re.compile(r"(?P<who>\b[^\W\d_]+(?:\s+[^\W\d_]+){0,2}?)['’]d\b", re.IGNORECASE)
# "would probably like", "could really use": a hedge after the helping verb is the speaker's
# doubt, the want unchanged (``want_hedges``)
_HEDGE = r"(?:\s+(?:" + phrase_alternatives("want_hedges") + r"))?"


def _hedged(key: str) -> str:
    """The phrases of ``key`` as alternatives, each with an optional hedge after its first
    word ("would probably like")."""
    phrases = sorted(english.entries(key), key=len, reverse=True)
    return "|".join(
        re.escape(first) + _HEDGE + "".join(r"\s+" + re.escape(w) for w in rest)
        for first, *rest in (p.split() for p in phrases)
    )


# "might want", "may want" said of a name are the same want put tentatively (``tentative_wants``)
_WANTING = re.compile(
    r"(?P<who>\b[^\W\d_]+(?:\s+[^\W\d_]+){0,2}?)\s+(?:"
    + _hedged("modal_wants")
    + "|"
    + _hedged("tentative_wants")
    + r")"
    r"(?=\s+" + _WANTED + ")",
    re.IGNORECASE,
)


_alternatives = english.alternation  # the lists' phrases as one regex alternation


# "Zhang is desperate for a coffee", "Zhang's also dying for a tea", "Zhang would kill for a
# coffee": the speaker's idioms of wanting (``wanting_idioms``) said of a name, after "is",
# "'s" or a helping verb and any degree or additive words: that colleague's want, like the
# speaker's own is theirs (``reading.purpose.wanting_idioms``)
_IDIOM_WANTING = re.compile(
    r"(?P<who>\b[^\W\d_]+(?:\s+[^\W\d_]+){0,2}?)(?:\s+(?:is|would|could)|['’]s)"
    rf"(?:\s+(?:{_alternatives('wanting_degrees', 'wanting_additives')}))*"
    rf"\s+(?:{_alternatives('wanting_idioms')})"
    r"(?=\s+(?:a|an|some|another|one|more)\b)",
    re.IGNORECASE,
)
# "would Zhang like a stapler?": the helping verb before the name that wants
# "Zhang would like to borrow my stapler", "Zhang might want to use your charger": the helping
# verb's want of having a thing (``borrow_words``, ``self_taking_verbs``) is the plain want,
# "Zhang wants to borrow my stapler", read as that is (a transfer to Zhang, asked alone); left
# as said, "would like to use" named nobody who wants it and the room it was taken to was asked
_HAVING = sorted(english.words("borrow_words") | english.words("self_taking_verbs"))
_WANTING_TO_HAVE = re.compile(
    r"(?P<who>\b[^\W\d_]+(?:\s+[^\W\d_]+){0,2}?)\s+(?:"
    + _hedged("modal_wants")
    + "|"
    + _hedged("tentative_wants")
    + r")\s+to\s+(?P<verb>"
    + "|".join(re.escape(v) for v in _HAVING)
    + r")(?=\s+"
    + _WANTED
    + ")",
    re.IGNORECASE,
)
_ASKED = re.compile(
    r"\bwould\s+(?P<who>[^\W\d_]+(?:\s+[^\W\d_]+){0,2}?)\s+(?:like|love)(?=\s+" + _WANTED + ")",
    re.IGNORECASE,
)


def named_wants(
    text: str, is_person: Callable[[str], bool], is_subject: Callable[[str], bool]
) -> str:
    """``text`` with each colleague's want said with a helping verb read as "<name> needs"
    (``is_person``: whether the words are one colleague's name; ``is_subject``: whether they
    are one in a subject's place, where a name that is also an English word, "frank",
    "mark", is read as the name: "frank could do with a radio" is Frank's want, never a
    request to take a colleague's radio to him at once)."""

    def said(match: re.Match[str]) -> str:
        said_who = match.group("who")
        # "I would like ..." names nobody and is left as said
        if named_tail(said_who, is_person) is None and not is_subject(said_who.split()[-1]):
            return match.group(0)
        return f"{said_who} needs"

    def asked(match: re.Match[str]) -> str:
        who = match.group("who")
        return f"{who} needs" if is_person(who) else match.group(0)

    def would(match: re.Match[str]) -> str:
        said_who = match.group("who")
        words = said_who.split()
        named = any(is_person(" ".join(words[k:])) for k in range(len(words)))
        return f"{said_who} would" if named else match.group(0)

    def wants_to_have(match: re.Match[str]) -> str:
        said_who = match.group("who")
        if named_tail(said_who, is_person) is None and not is_subject(said_who.split()[-1]):
            return match.group(0)
        return f"{said_who} wants to {match.group('verb')}"

    text = _WANTING_TO_HAVE.sub(wants_to_have, _WOULD.sub(would, text))
    text = _IDIOM_WANTING.sub(said, text)
    return _ASKED.sub(asked, _WANTING.sub(said, text))


# "Chinedu has run out of zip ties", "Wang ran out of paper" ("'s run out" is "has run out" by
# now): a colleague's supply used up (``used_up_phrases``), said to an assistant that fetches
# the office's supplies, is that colleague's want of more (blind round 254: "chinedu's run out
# of zip ties down at the valet bay" was only noted)
_RUN_OUT = re.compile(
    r"(?P<who>\b[^\W\d_]+(?:\s+[^\W\d_]+){0,2}?)(?:\s+(?:"
    + _alternatives("used_up_phrases")
    + r")|['’]s\s+(?:"
    + _alternatives("contracted_used_up_phrases")
    + r"))(?=\s+(?P<thing>[^\W\d_]+(?:[\s-]+[^\W\d_]+){0,3}))",
    re.IGNORECASE,
)


def named_lacks(
    text: str,
    is_person: Callable[[str], bool],
    is_subject: Callable[[str], bool],
    used_up: Callable[[str], bool],
) -> str:
    """``text`` with a colleague's used-up supply read as "<name> needs <thing>"
    (``used_up``: whether the words after the lack open with a supply the office gives
    anyone and uses up; a thing of their own, a machine's paper
    ("the printer has run out of paper") and "I've run out" are left as said)."""

    def said(match: re.Match[str]) -> str:
        said_who = match.group("who")
        if named_tail(said_who, is_person) is None and not is_subject(said_who.split()[-1]):
            return match.group(0)
        if not used_up(match.group("thing")):
            return match.group(0)
        return f"{said_who} needs"

    return _RUN_OUT.sub(said, text)
