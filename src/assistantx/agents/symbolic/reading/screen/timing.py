"""When, said in an idiom of time rather than a time ("when you get a sec", "when you've a
minute", "in a tick", "whenever"): set aside before the pieces are judged, so its noun is never
read as a thing asked for ("there is no sec in this office") and what is left is read alone
("can u bring it down to me" still asks which item "it" is). An idiom whose noun goes on into
a phrase ("in a second envelope") or is the office's own item is left as said.

A clause that waits for someone else ("when he's back from lunch", "once Zhang is free", "as
soon as she gets in") is set aside the same way: it says when, not what, so "lunch" is no thing
to fetch. Only a third person's being back, in, free or done counts: "once you've printed it"
is a step of the errand, and stays."""

from __future__ import annotations

import re

from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.core import english
from assistantx.core.task_schema import Evidence

# The nouns of a short while: "a sec", "a mo", "a tick", "a spare minute".
_WHILE_NOUN = r"(?:secs?|seconds?|mins?|minutes?|mo|moments?|ticks?|jiffy|chance|bit|while|tic)"
_WHILE = rf"(?:spare\s+|free\s+|quick\s+|few\s+)?{_WHILE_NOUN}"


def is_while_noun(word: str) -> bool:
    """Whether ``word`` names a short while ("sec", "min", "tick"), as the idioms of time
    here read it ("give me a min" asks for one, ``curious.asks_for_time``)."""
    return re.fullmatch(_WHILE_NOUN, word, re.IGNORECASE) is not None


_YOU = r"(?:you|u|ya|yo)"
_HAVE = r"(?:'ve\s+got|'ve|\s+have\s+got|\s+have|\s+get|\s+got|\s+find|\s+are\s+free|'re\s+free)"
# "when you get a sec", "whenever you've a minute", "in a tick", "whenever (you can)": each
# must end its clause (a stop, a comma, a join or a courtesy, or the end of the message), or
# open the request said right after it unpunctuated: its modal and "you" ("when you get a sec
# could you print ..."), or an errand's verb in the imperative ("when you get a sec grab me a
# pen": the word after it, ``next``, is checked against the office's errand verbs)
_ASKED_NEXT = rf"(?:{'|'.join(sorted(english.words('request_modals')))})\s+(?:you|u|ya)\b"
_END = (
    r"(?=\s*(?:$|[.,;:!?)…-]|(?:and|then|please|pls|plz|thanks|thank|thx|ta|cheers|x)\b"
    rf"|{_ASKED_NEXT})|\s+(?P<next>[^\W\d_]+)\b)"
)
_IDIOM = re.compile(
    r"(?:,\s*)?\b(?:"
    rf"when(?:ever)?\s+{_YOU}{_HAVE}\s+(?:a|the)\s+{_WHILE}"
    rf"|in\s+a\s+{_WHILE}"
    rf"|whenever(?:\s+{_YOU}\s+can|\s+{_YOU}(?:'re|\s+are)\s+free)?"
    rf"){_END}",
    re.IGNORECASE,
)

# "when he's back from lunch", "once Zhang is free", "as soon as she gets in", "after they're
# out of the meeting": the clause runs to the next stop or comma.
_WAITED = re.compile(
    r"(?:,\s*)?\b(?:when|once|as\s+soon\s+as|after)\s+(?P<who>[^\W\d_]+)"
    r"(?:'s|\s+is|'re|\s+are|\s+gets?|\s+comes?|\s+has\s+got|\s+has)\s+"
    r"(?:back|in|free|done|finished|out|off|around|available|up)\b[^.,;:!?]*",
    re.IGNORECASE,
)
_THIRD_PERSONS = frozenset({"he", "she", "they", "hes", "shes"})


def without_time_idioms(terms: Terms, text: str) -> tuple[str, list[Evidence]]:
    """``text`` without its idioms of time, each kept as evidence of how it was read."""
    found: list[Evidence] = []

    def drop(match: re.Match[str]) -> str:
        said = re.findall(r"[a-z]+", match.group(0).lower())
        if said[-1] in terms.lex.items:
            return match.group(0)  # the office's own thing, not a while
        following = match.group("next")
        if following is not None and following.lower() not in terms.lex.cue_words:
            return match.group(0)  # "in a bit of a rush", "when you get a sec I ...": said on
        found.append(Evidence(words=match.group(0).strip(" ,"), meaning="when: soon, no time"))
        return ""

    def waited(match: re.Match[str]) -> str:
        who = match.group("who").lower()
        if who not in _THIRD_PERSONS and who not in terms.lex.name_words:
            return match.group(0)  # "once you're back", "when it is done": not someone else
        if who not in _THIRD_PERSONS and match.string[match.end() :].strip(" .!?"):
            return match.group(0)  # "once Miles is free, take it to him": the name is wanted
        found.append(Evidence(words=match.group(0).strip(" ,"), meaning="when: once they can"))
        return ""

    left = _WAITED.sub(waited, _IDIOM.sub(drop, text))
    return (re.sub(r"\s{2,}", " ", left).strip(), found) if found else (text, [])
