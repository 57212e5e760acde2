"""A pronoun's contraction kept as two words before any word of it is looked up.

The reader folds a word's apostrophe away, so "he'll" becomes "hell", "she'll" "shell",
"we'll" "well": other English words, which the typo and verb
stages then read as something else ("give Will my letter, she'll frank it later" was declined
"Sorry, I can't shell frank"). Written "she 'll", the subject stays a word of its own and the
clause keeps the person who will do the thing: their plan, never a task for the robot.

The same holds where the apostrophe was never typed and the fused spelling is a noun that
cannot be one there: "hell"/"shell" opening a clause and followed by the plain form of a
verb ("..., shell frank it tonight") is "she'll"; "the shell", "what the hell" and "hell
yes" are left as said.
"""

from __future__ import annotations

import re

from assistantx.core import language
from assistantx.core.task_schema import Evidence

# A pronoun other than the speaker's "I" with its contracted auxiliary, in either apostrophe.
# "I'll"/"I'd" are not here: the speaker's own future is read by rules that match "I'll" and
# "Ill" themselves (``reading.future_need``, ``reading.announced_borrowing``).
# Only "'ll": "we're" ("were"), "we'd" ("wed") and "she'd" are read by the rules for them as
# they fold ("we're out of tape" is the speaker's lack), and keep their spelling.
_CONTRACTED = re.compile(r"\b(he|she|we|they|you|it|that|there|who)['’](ll)\b", re.IGNORECASE)
# "hell"/"shell" typed for "he'll"/"she'll": only where a clause opens (the message's start,
# a stop or a comma, or a joining word), never after a determiner ("the shell").
_UNTYPED = re.compile(
    r"(^|[.!?;,]\s*|\n\s*|\b(?:and|so|but|cos|because)\s+)(h|sh)(ell)\s+([a-z]+)\b",
    re.IGNORECASE,
)
# Words that follow a future's auxiliary without being its verb's plain form.
_ADVERBS = frozenset({"probably", "definitely", "just", "also", "still", "likely", "surely"})
# Particles that are verbs too ("up"): after "shell" they make the verb "shell out/up".
_PARTICLES = frozenset({"out", "up", "off", "on", "in", "down", "over"})


def contractions_apart(text: str) -> tuple[str, list[Evidence]]:
    """``text`` with each pronoun's contraction written as two words ("she'll" → "she 'll")
    whose folded spelling would be another English word, and "hell"/"shell" opening a clause
    before a plain verb read as "he 'll"/"she 'll"."""
    found: list[Evidence] = []

    def apart(match: re.Match[str]) -> str:
        pronoun, ending = match.group(1), match.group(2)
        if not language.is_english_word(f"{pronoun}{ending}".lower()):
            return match.group(0)  # "they'll", "you've": no other word when folded
        found.append(Evidence(words=match.group(0), meaning=f"{pronoun} '{ending}: a contraction"))
        return f"{pronoun} '{ending}"

    def untyped(match: re.Match[str]) -> str:
        verb = match.group(4).lower()
        if verb in _PARTICLES or not (verb in _ADVERBS or verb in language.verb_lemmas(verb)):
            return match.group(0)  # "hell yes", "shell out" read as said
        pronoun = "he" if match.group(2).lower() == "h" else "she"
        if match.group(2)[0].isupper():
            pronoun = pronoun.capitalize()
        said = f"{pronoun} 'll"
        found.append(Evidence(words=match.group(0).strip(" ,.;"), meaning=f"{said}: untyped"))
        return f"{match.group(1)}{said} {match.group(4)}"

    text = _CONTRACTED.sub(apart, text)
    return _UNTYPED.sub(untyped, text), found
