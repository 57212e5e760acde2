"""A clause of when run into the command after it with no comma: "when Wang is at the printer
give him my file", "once Zhang gets back take her the stapler", "as soon as he's in bring him
a coffee". Said with its comma the clause is read as a condition and the command as the
request; run in, the whole was read as one clause (answered as a question about the printer,
or asked what was wanted). The comma is put back before the command: a task's word in its
plain form after the clause's subject and verb, never after a determiner, a preposition, "to",
a subject or a modal ("when Wang needs to print ...", "once the print run ends": no command).
"""

from __future__ import annotations

import re
from collections.abc import Collection

from assistantx.core import english, language

_OPENER = re.compile(
    r"(?:^|(?<=[.!?;]\s))\s*(?:when|whenever|once|as\s+soon\s+as)\s+(?P<clause>[^.,;:!?]+)",
    re.IGNORECASE,
)
_WORD = re.compile(r"[\w']+")
# what a task's word after it is no command for: its article, its preposition, its subject
# (an "it" before it is the clause's object: "when Wang prints it bring it here"; "in", "back"
# end a clause of being: "once he's in bring him a pen")
_NOT_BEFORE_COMMAND = (
    english.words("determiners")
    | (english.words("subject_pronouns") - {"it"})
    | english.words("request_modals")
    | frozenset({"to", "from", "of", "for", "with", "by", "and", "or", "not"})
)
_FIRST_COMMAND = 2  # the clause's subject and its verb come first


def paused_when_clause(text: str, cue_words: Collection[str]) -> str:
    """``text`` with a comma put back between a clause of when that opens a sentence and the
    command run into it."""

    def paused(match: re.Match[str]) -> str:
        clause = match.group("clause")
        words = list(_WORD.finditer(clause))
        for n in range(_FIRST_COMMAND, len(words)):
            said = words[n].group(0).lower()
            before = words[n - 1].group(0).lower()
            if said not in cue_words or before in _NOT_BEFORE_COMMAND:
                continue
            if said not in language.verb_lemmas(said):
                continue  # "when Wang prints it": the clause's own verb, not a command
            at = match.start("clause") + words[n].start()
            head = match.string[match.start() : at].rstrip()
            return f"{head}, {match.string[at : match.end()]}"
        return match.group(0)

    return _OPENER.sub(paused, text)
