"""The requester's answer to "Who do you mean by 'Tomás': Tomáš Novák or Tomás Herrera?".

The answer that names exactly one of the people offered ("Tomás Herrera", "Herrera", "the
first one" is not read here) takes the place of the name asked about in the request: "bring it
to Tomás in Studio A" becomes "bring it to Tomás Herrera in Studio A", which the reader then
reads as any request with a full name. Appending the answer to the request instead ("... in
Studio A. Tomás Herrera") leaves the ambiguous name where it was, and the same question came
back until the task failed with "your answer did not tell me"."""

from __future__ import annotations

import re

from assistantx.agents.symbolic.reading.lexicon import Lexicon
from assistantx.core import language

# The reader's own question (readings._doubts): the name said, then the people it may mean.
_ASKED = re.compile(r"^Who do you mean by '(?P<said>.+?)': (?P<names>.+)\?$")


def with_name_chosen(lex: Lexicon, text: str, question: str, answer: str) -> str | None:
    """The request with the asked-about name replaced by the chosen person's full name;
    None when the question is not this one or the answer names none or several of them."""
    asked = _ASKED.match(question)
    if asked is None:
        return None
    by_name = {p.name: p.id for p in lex.office.people}
    offered = {by_name[n] for n in asked.group("names").split(" or ") if n in by_name}
    if len(offered) < 2:
        return None
    named = {i for m in lex.read(answer).mentions if m.kind == "person" for i in m.ids}
    chosen = named & offered
    if len(chosen) != 1:
        return None
    person = chosen.pop()
    lexed = lex.read(text)
    spans = list(language.WORD.finditer(text.replace("’", "'")))
    for m in lexed.mentions:
        if m.kind != "person" or len(m.ids) < 2 or not offered <= set(m.ids):
            continue
        start, end = spans[m.start].start(), spans[m.end - 1].end()
        # "Tomás's": the possessive goes with the full name ("James'": its apostrophe stays)
        owned = m.possessive and not text[end:].startswith(("'", "’"))
        full = lex.office.person(person).name + ("'s" if owned else "")
        return f"{text[:start]}{full}{text[end:]}"
    return None
