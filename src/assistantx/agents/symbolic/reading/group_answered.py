"""The answer to "Should the stapler go to Wang Fang, or to Sun Li?" (one thing said for a
group of recipients, ``joined_recipients``): the group in the request is replaced by the one
colleague the answer names ("Wang and Sun need a stapler" + "Wang" → "Wang Fang need a
stapler"), read again as any request; an answer that names none or several of them leaves
the question open."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.joined_recipients import ONLY_ONE, group_spans
from assistantx.agents.symbolic.reading.lexicon import Lexicon
from assistantx.core import language


def with_one_of_group(lex: Lexicon, text: str, question: str, answer: str) -> str | None:
    """The request with the group replaced by the one the answer names, or None."""
    if not question.endswith(ONLY_ONE):
        return None
    named = {i for m in lex.read(answer).mentions if m.kind == "person" for i in m.ids}
    lexed = lex.read(text)
    spans = list(language.WORD.finditer(text.replace("’", "'")))
    for start, end in group_spans(lexed.tokens, lexed.mentions):
        group = {
            i
            for m in lexed.mentions
            if m.kind == "person" and start <= m.start < end
            for i in m.ids
        }
        chosen = named & group
        if len(chosen) != 1:
            continue
        name = lex.office.person(chosen.pop()).name
        return f"{text[: spans[start].start()]}{name}{text[spans[end - 1].end() :]}"
    return None
