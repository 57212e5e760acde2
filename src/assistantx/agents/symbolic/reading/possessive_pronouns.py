"""A possessive pronoun said for a thing named before: "Inés and Thảo both sent retouches.
print hers and bring it to me", "can someone lend me theirs". "hers" is "her one": the thing
of the kind just named, of whoever "her" is (asked when two are named). Read as said, "hers"
named nothing and the speaker's own file was printed. Only as the object of a verb of doing or
after whom it goes to ("is this pen hers?" says whose it is). "his" is left as said: it is
also the determiner ("his stapler"), and "his one" loses its owner to "one"; "mine" and
"yours" have their own readings (``rewrites.dangling_possessives``)."""

from __future__ import annotations

import re

from assistantx.core import language

# what may follow the pronoun where it stands for the thing: the end of the message or a
# clause, or a join or courtesy ("print hers and bring it to me", "his please")
_AFTER = r"(?=\s*(?:$|[.,!?;:]|(?:and|please|pls|plz|too|then|as well|for me|to me)\b))"
_PRONOUNS = re.compile(r"\b(?P<p>hers|theirs)\b" + _AFTER, re.IGNORECASE)
_AS_DETERMINER = {"hers": "her", "theirs": "their"}
# whom a thing is given to, said before it ("bring me hers")
_GIVEN_TO_END = re.compile(r"\b(?:me|us|him|them)\s*$", re.IGNORECASE)
# verbs that say what a thing is ("is this pen his?"), never what is done with it
_BEING = frozenset({"is", "are", "was", "were", "be", "been", "s", "isnt", "arent"})
# a verb said to the robot: opening the message or a clause, or after "you", a courtesy or
# a join ("print hers", "... job. print hers", "could you borrow hers", "and print hers")
_ASKED_VERB_END = re.compile(
    r"(?:^|[.!?;:,]\s*|\b(?:you|u|ya|please|pls|plz|and|then|just|to)\s+)(?P<verb>[a-z]+)\s*$",
    re.IGNORECASE,
)


def possessive_pronouns(text: str) -> str:
    """``text`` with each possessive pronoun that stands for a thing said as "<her> one"."""

    def one(m: re.Match[str]) -> str:
        said = m.group("p")
        if not _object_slot(text[: m.start()]):
            return said
        word = _AS_DETERMINER[said.lower()]
        return f"{word.capitalize() if said[:1].isupper() else word} one"

    return _PRONOUNS.sub(one, text)


def _object_slot(before: str) -> bool:
    """Whether the words ``before`` the pronoun make it the robot's object: whom it goes to
    ("bring me hers") or a verb said to the robot, opening its clause ("print hers", "could
    you borrow hers"); "Will needs hers", "she's using hers" are what another does."""
    given = _GIVEN_TO_END.search(before)
    if given is not None:
        return True
    asked = _ASKED_VERB_END.search(before)
    if asked is None:
        return False
    verb = asked.group("verb").lower()
    return verb not in _BEING and "VERB" in language.lemmas(verb)
