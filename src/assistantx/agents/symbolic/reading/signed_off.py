"""A chat sign-off after a request: "heat it ta", "send my file to Wang x", "copy my contract
ta v much", "bring me a stapler xx".

People close a chat message with a word of thanks, a kiss or a laugh (``chat_sign_offs`` in
english.yaml), often with no stop before it. Said right after a request it only closes the
message: the thanks word within a short piece's first words made the whole request a thanks
("heat it ta": "You're welcome! I did nothing."), and a word run into the request's last
noun was read as part of it ("my lunch cheers" asked which item). The step takes the run of
sign-offs off the end of a message whose words before it ask for the office's work (one of
its task words is said), so the request is read as it would be without them.

Left as they are: a sign-off set off by a stop or a comma ("..., ta": the screen reads it as
a thanks piece of its own, beside the request); a message that is nothing but thanks ("ta",
"thanks, that's all"), or whose words before it name no task; and a word that is a
colleague's name or alias in the office ("send my file to Ta"): the name wins."""

from __future__ import annotations

import re
from collections.abc import Callable, Set

from assistantx.core import english, language

_SIGN_OFFS = sorted(english.entries("chat_sign_offs"), key=len, reverse=True)
_ONE = "|".join(
    # a word sign-off ends at a word's end ("ta", never "tap"); an emoticon as written
    re.escape(s) + (r"(?![\w'])" if s[-1].isalnum() else "")
    for s in _SIGN_OFFS
)
# one or more sign-offs at the very end, each after a space (none after a stop or a comma)
_CLOSING = re.compile(rf"(?<=[\w'])(?:\s+(?:{_ONE}))+[\s.!]*$", re.IGNORECASE)
_WORD = re.compile(r"[\w']+")


def without_sign_off(text: str, task_words: Set[str], is_name: Callable[[str], bool]) -> str:
    """``text`` without the sign-offs that close it after a request; as it is where there are
    none, where they stand alone or after no task word, or where one is a colleague's name."""
    found = _CLOSING.search(text)
    if found is None:
        return text
    closing = found.group(0)
    if any(is_name(w) for w in _WORD.findall(closing.lower())):
        return text  # "send my file to Ta": a colleague, not a thanks
    before = text[: found.start()].rstrip()
    words = _WORD.findall(before.lower())
    if not any(w in task_words or language.verb_lemmas(w) & task_words for w in words):
        return text  # "thank you x", "ok cheers": nothing asked to close
    return before
