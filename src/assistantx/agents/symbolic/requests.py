"""Whether a direct message asks for something, before it may start an instruction.

A direct message that answers no open question starts an instruction only when it is a
request. Two strengths of evidence:

- *explicit*: request wording ("please", "can you", "I need", ...) or a sentence that starts
  with an operation's verb ("bring me ...", "print ...");
- *understood*: the instruction parser finds tasks in it, or a request it can ask about
  ("bring me his stapler" → "who do you mean by his?"), not "I'm not sure what you need".

A colleague who was just contacted by an instruction that has ended ("I came to the robot,
but: I don't have a stapler", "Yes, I have one") is writing about that instruction: the parser
would read an item and a person as a hand-over, so only explicit wording counts there.
"""

from __future__ import annotations

import re

from assistantx.agents.symbolic.reading.parser import NOT_UNDERSTOOD, shared_parser
from assistantx.agents.symbolic.reading.screen import UNANSWERED
from assistantx.core import english
from assistantx.core.office import Office

_REQUEST_WORDING = re.compile(
    r"\b(please|pls|plz|can you|could you|would you|will you|i need|we need|i want|"
    r"i'd like|i would like|help me|i'd need)\b",
    re.IGNORECASE,
)
_OPENERS = english.words("openers")
# What the screen calls a piece that neither asks for nor about anything (``screen``).
_SAID_ONLY = frozenset({"thanks, not a request", "a statement, context only", UNANSWERED})


class RequestRecognizer:
    """``recognizer(text, sender, strict=...)``: True when ``text`` is a request."""

    def __init__(self, office: Office) -> None:
        self._parser = shared_parser(office)  # the reasoner's: no second lexicon to build
        self._lex = self._parser.lex

    def __call__(self, text: str, sender: str, *, strict: bool) -> bool:
        if self.explicit(text):
            return True
        if strict:
            return False
        frame = self._parser.parse(text, sender)
        if frame.decline is not None and all(e.meaning in _SAID_ONLY for e in frame.evidence):
            return False  # thanks or a statement: nothing to act on, nothing to answer
        if frame.understood or frame.decline is not None:
            return True  # a declined request is still answered with its reason
        return frame.question is not None and frame.question != NOT_UNDERSTOOD

    def explicit(self, text: str) -> bool:
        if _REQUEST_WORDING.search(text):
            return True
        for sentence in re.split(r"[.!?;]\s+|\n", text):
            tokens = self._lex.tokens(sentence)
            first = next((n for n, t in enumerate(tokens) if t.word not in _OPENERS), None)
            if first is None:
                continue
            if any(m.kind == "cue" and m.start == first for m in self._lex.scan(tokens)):
                return True
        return False
