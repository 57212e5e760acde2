"""A colleague's thing asked for by what it holds, its form said in the next sentence: "Can you
get me this week's rota numbers from Wang? She keeps them in a spreadsheet", "could I have the
quarterly figures from Ana? They're in a pdf".

"<what it holds> from <colleague>" names the colleague's thing by its content; a sentence after
it that says the content is kept in one of the office's electronic files ("she keeps them in a
spreadsheet", "it's in a pdf", "they're on a spreadsheet") says which thing that is: the
colleague's file, forwarded as any file of theirs is. The content is then only a description
of that file, and is left out as a hyphened description is (``described_items``): "get me
Wang's spreadsheet", so the reader reads the colleague's file, and never a thing of the
office one of the content's words names ("the quarterly cake numbers" is no cake). Without
such a sentence the content is read as before (asked about when the office has nothing of
that name).
"""

from __future__ import annotations

import re
from collections.abc import Callable

from assistantx.core import english

# "She keeps them in a spreadsheet", "he has it on a pdf", "it's in a spreadsheet", "they're
# all in one pdf": the content's form, said of its keeper or of the content itself
_FORM_SAID = re.compile(
    r"^\s*(?:(?:she|he|they|[A-Z][\w'’-]*)\s+(?:keeps|has|stores|saves|puts|kept|had|saved|"
    r"has\s+got|['’]s\s+got)\s+(?:them|it|those|that)|(?:it|they|those|that)\s*"
    r"(?:['’]s|['’]re|\s+is|\s+are)(?:\s+all)?)\s+(?:in|on)\s+(?:a|an|one|the|her|his|their)\s+"
    r"(?P<form>[a-z][\w -]*?)\s*[.!]?\s*$",
    re.IGNORECASE,
)
# "... <content> from <colleague>" ending its sentence ("?" or "."), the content after the verb's
# first object ("get me", "send us") or the verb
_OBJECTS = "|".join(sorted(english.words("object_pronouns") | {"me", "us"}))
_VERBS = "|".join(sorted(english.words("dative_verbs") | english.words("wish_verbs") | {"have"}))
_FROM = re.compile(
    rf"(?P<lead>\b(?:{_OBJECTS}|{_VERBS})\s+)"
    rf"(?P<content>(?!(?:{_OBJECTS}|me|us)\b)(?:[\w'’-]+\s+){{0,5}}?[\w'’-]+)"
    r"\s+from\s+(?P<person>[\w'’ -]+?)\s*(?P<end>[?.!])",
    re.IGNORECASE,
)
_SENTENCE = re.compile(r"(?<=[?.!])\s+")


def with_form_said_after(
    text: str,
    as_file: Callable[[str], str | None],
    is_person: Callable[[str], bool],
) -> str:
    """``text`` with a colleague's content asked for, whose form the next sentence says is one
    of the office's files, said as that colleague's file ("get me Wang's spreadsheet?");
    ``as_file``: the phrase said as the office's file where it names one, ``is_person``:
    whether a phrase is a colleague's name."""
    sentences = _SENTENCE.split(text)
    if len(sentences) < 2:
        return text
    for n in range(1, len(sentences)):
        said = _FORM_SAID.match(sentences[n])
        if said is None:
            continue
        form = said.group("form").strip()
        if as_file(form) != form:
            continue  # "she keeps them in a drawer": no file of the office
        asked = _FROM.search(sentences[n - 1])
        if asked is None or not is_person(asked.group("person").strip()):
            continue
        if as_file(asked.group("content")) == asked.group("content"):
            continue  # "the rota spreadsheet from Wang": the file already said
        said_before = sentences[n - 1]
        owner = asked.group("person").strip()
        sentences[n - 1] = (
            f"{said_before[: asked.start('content')]}{owner}'s {form}"
            f"{said_before[asked.end('person') :]}"
        )
        return " ".join(sentences)
    return text
