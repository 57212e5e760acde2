"""A request reported on a colleague's behalf: "Professor Zhang asked if someone could bring
him a coffee, can you do that?", "Ana was wondering if anyone could take her the stapler". The
one reported asks for themselves: "him"/"her" in the reported request is that colleague, who
receives. It is read as the request itself ("could someone bring Professor Zhang a coffee"),
so the frames read the colleague as its recipient; "his"/"her" before where the thing goes
("bring it to her desk") is theirs too. "she"/"he" as the one reported is the one colleague
the message named before ("Chen's lunch is in the fridge, she asked if someone could bring
it to her desk"). A report with no such ask ("Zhang asked
about the rota") is left alone, and so is one whose reported speaker is no colleague."""

from __future__ import annotations

import re
from collections.abc import Callable

from assistantx.core import english


def phrase_alternatives(key: str) -> str:
    """A regex alternation of the phrases of english.yaml's list ``key``, longest first,
    any run of spaces between their words."""
    phrases = sorted(english.entries(key), key=len, reverse=True)
    return "|".join(r"\s+".join(re.escape(w) for w in p.split()) for p in phrases)


_REPORTED = re.compile(
    r"(?P<who>\b[^\W\d_]+(?:\s+[^\W\d_]+){0,2}?)\s+(?:"
    + phrase_alternatives("reporting_asks")
    + r")"
    r"\s+(?:if|whether)\s+(?P<doer>" + phrase_alternatives("reported_doers") + r")\s+"
    r"(?P<modal>could|can|would|will|might)\s+(?P<rest>[^.?!;]*)",
    re.IGNORECASE,
)
# "him"/"her" as whom something goes to: before what is given, after "to"/"for", or ending
# the request ("bring it over to her")
_RECEIVING = re.compile(
    r"\b(?P<p>him|her)\b"
    r"(?=\s+(?:a|an|the|some|one|another|his|her|their|my|over|up|down|back|round|across|it|"
    r"them)\b|\s*[,]|\s*$)",
    re.IGNORECASE,
)


# "his"/"her" before a noun in the reported request: the colleague's ("to her desk")
_OWNING = re.compile(r"\b(?:his|her)\b(?=\s+[^\W\d_])", re.IGNORECASE)
# ... where it says where the thing goes: "to Chen's desk"
_TO_OWN = re.compile(r"\b(?:to|over\s+to|up\s+to)\s+[^\W\d_][\w ]*?['’]s\b", re.IGNORECASE)
_SUBJECT_PRONOUNS = frozenset({"he", "she"})
_WORD = re.compile(r"[^\W\d_]+")
_POSSESSIVE = re.compile(r"['’]s\b")


def _one_named_before(text: str, is_person: Callable[[str], bool]) -> str | None:
    """The one colleague ``text`` names (as said, longest name first), or None where it
    names none or several."""
    words = _WORD.findall(_POSSESSIVE.sub("", text))  # "Chen's lunch": Chen
    found: list[str] = []
    k = 0
    while k < len(words):
        for n in (3, 2, 1):
            phrase = " ".join(words[k : k + n])
            if len(words[k : k + n]) == n and is_person(phrase):
                found.append(phrase)
                k += n
                break
        else:
            k += 1
    return found[0] if len(set(found)) == 1 else None


def reported_requests(text: str, is_person: Callable[[str], bool]) -> str:
    """``text`` with each request a colleague is reported to have made read as the request
    for them (``is_person``: whether the words are one colleague's name)."""

    def said(match: re.Match[str]) -> str:
        said_who = match.group("who")
        who = named_tail(said_who, is_person)  # "so Ana was wondering": Ana
        lead = said_who[: len(said_who) - len(who)] if who is not None else ""
        if who is None and said_who.split()[-1].lower() in _SUBJECT_PRONOUNS:
            # "Chen's lunch is in the fridge, she asked if someone could bring it": the one
            # colleague the message named before is "she"
            who = _one_named_before(text[: match.start()], is_person)
            lead = said_who[: len(said_who) - len(said_who.split()[-1])]
        if who is None:
            return match.group(0)
        rest, found = _RECEIVING.subn(who, match.group("rest"))
        # "... bring it to her desk": whose desk it goes to is the colleague's
        rest, owned = _OWNING.subn(f"{who}'s", rest)
        if not found and not (owned and _TO_OWN.search(rest)):
            return match.group(0)
        return f"{lead}{match.group('modal')} {match.group('doer')} {rest}"

    return _REPORTED.sub(said, text)


def named_tail(said: str, is_person: Callable[[str], bool]) -> str | None:
    """The longest tail of the words ``said`` that is one colleague's name ("Professor
    Zhang", "Liu Yang", "so Ana": Ana), or None where no tail is."""
    words = said.split()
    tails = (" ".join(words[k:]) for k in range(len(words)))
    return next((t for t in tails if is_person(t)), None)
