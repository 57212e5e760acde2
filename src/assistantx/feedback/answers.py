"""Reading survey replies the way people write them.

The survey asks four yes / no / unsure questions and invites an optional comment. People
answer in many shapes, and all of these read the same::

    1. yes 2. no 3 unsure 4 yes      numbered, any punctuation
    yes yes no yes                   in order
    y/n/?/y   yyn?   👍 👎 🤷 👍     short forms and emoji
    all yes   yes to all             one answer for every open question
    no                               one answer: the next open question
    yes yes no yes - it was quick    answers, then a comment
    comment: the robot was slow      an explicit comment

What counts as a comment: text with at least one word of two or more letters that is not
keyboard mash (``says_something``). Mash is a word made only of runs of three or more keys
side by side on one keyboard row, either way ("asdf", "qwerty", "lkj", "asdfasdf"), or one
letter repeated ("aaaa"); so "asdf qwerty" is an unreadable reply, never a comment, while
"too slow" or "gut" is one, in any language written in letters.

``parse_reply`` only reads; what a reply means for a survey (which question a lone "no"
answers, whether unreadable text is a comment, nonsense or a new request) is decided by the
survey state machine in ``survey.py``. Words that are neither answers nor fillers are kept in
``unclear`` so nothing the person wrote is silently dropped.
"""

from __future__ import annotations

import functools
import re
from dataclasses import dataclass, field
from typing import Literal

Choice = Literal["yes", "no", "unsure"]
CHOICES: tuple[Choice, ...] = ("yes", "no", "unsure")
QUESTION_COUNT = 4

_YES = {
    "yes", "y", "yeah", "yea", "yep", "yup", "ya", "sure", "true", "definitely", "absolutely",
    "certainly", "indeed", "correct", "👍", "✅", "✔", "☑",
}  # fmt: skip
_NO = {
    "no", "n", "nope", "nah", "false", "never", "negative", "👎", "❌", "✗", "✖",
}  # fmt: skip
_UNSURE = {
    "unsure", "?", "maybe", "dunno", "idk", "perhaps", "partly", "partially", "somewhat",
    "neutral", "unclear", "mixed", "🤷",
}  # fmt: skip
_WORDS: dict[str, Choice] = {
    **dict.fromkeys(_YES, "yes"),
    **dict.fromkeys(_NO, "no"),
    **dict.fromkeys(_UNSURE, "unsure"),
}
# Phrases read as one answer; replaced (padded to the same length, so positions in the text
# still match the original) by a one-letter answer before the text is split into words.
_PHRASES: tuple[tuple[re.Pattern[str], str], ...] = tuple(
    (re.compile(pattern), word)
    for pattern, word in (
        (r"\bnot\s+(?:really|at\s+all|much|quite)\b", "n"),
        (r"\b(?:not\s+sure|don'?t\s+know|do\s+not\s+know|no\s+idea|can'?t\s+say)\b", "?"),
        (r"\b(?:kind\s+of|sort\s+of|so[\s-]so|more\s+or\s+less)\b", "?"),
        (r"\bn\s*/\s*a\b", "?"),
        (r"\bof\s+course\b", "y"),
    )
)
# Words that carry no answer ("I think yes", "1 is yes", "yes to all, thanks").
_FILLERS = {
    "and", "to", "the", "for", "question", "questions", "q", "is", "it", "was", "i", "think",
    "answer", "answers", "a", "my", "are", "thanks", "thank", "you", "please", "hi", "hello",
    "all", "every", "everything", "each", "of", "them", "on", "=", "then", "also", "would",
    "say", "number", "ok", "okay", "except", "but", "so", "well", "hmm", "um",
}  # fmt: skip
_ALL_WORDS = {"all", "every", "everything", "each"}
# "comment: ..." anywhere, or "5. ..." / "q5: ..." at the start of a line (question 5 is the
# optional comment).
_COMMENT_MARK = re.compile(
    r"(?:^|(?<=[\s,;.]))(?:comments?|notes?|feedback|remarks?)\s*[:=\-]\s*(?=\S)"
    r"|(?:^|(?<=\n))\s*q?5\s*[:.)]\s*(?=\S)",
    re.IGNORECASE,
)
_TOKEN = re.compile(r"q?\d+|[^\W\d_]+(?:'[^\W\d_]+)?|[^\w\s]", re.UNICODE)
_COMPACT = re.compile(r"^[yn?]{2,4}$")

_OPT_OUT = re.compile(
    r"\b(?:stop|no\s+more|unsubscribe|opt[\s-]?out\s+(?:of\s+)?|don'?t\s+(?:send|want)|"
    r"do\s+not\s+send|quit)\b[\w\s]*\bsurveys?\b"
    r"|^\s*(?:stop|unsubscribe|opt[\s-]?out)\s*[.!]*\s*$",
    re.IGNORECASE,
)
_OPT_IN = re.compile(
    r"\b(?:start|resume|restart|send\s+me|opt[\s-]?in\s+(?:to\s+)?)\b[\w\s]*\bsurveys?\b"
    r"|^\s*opt[\s-]?in\s*[.!]*\s*$",
    re.IGNORECASE,
)
_SKIP = re.compile(
    r"^\s*(?:skip|skip\s+(?:it|this|the\s+survey)|no\s+thanks?|not\s+now|later|pass)\s*[.!]*\s*$",
    re.IGNORECASE,
)
# Starts of messages that ask the assistant to do something: a new instruction, never a
# survey comment. Checked after greetings and politeness are stripped.
_REQUEST = re.compile(
    r"^(?:(?:hi|hey|hello|ok|okay|assistant|robot)[\s,!.]+)*(?:please\s+|pls\s+)?"
    r"(?:(?:can|could|would|will)\s+you\s+(?:please\s+)?|i\s+(?:need|want|would\s+like)\s+)?"
    r"(?:bring|get|fetch|take|deliver|print|copy|send|forward|ask|tell|find|pick|collect|"
    r"carry|make|sign|heat|go|move|remind|book|return|give|drop|borrow|lend|check|let)\b",
    re.IGNORECASE,
)


@dataclass(frozen=True)
class ParsedReply:
    """What a reply says, before it is matched to a survey's open questions."""

    numbered: dict[int, Choice] = field(default_factory=dict)
    """Answers to a named question (1-based)."""
    ordered: tuple[Choice, ...] = ()
    """Answers without a number, for the open questions in order."""
    to_all: Choice | None = None
    """One answer for every open question ("all yes")."""
    comment: str | None = None
    unclear: tuple[str, ...] = ()
    """Words read neither as an answer nor as a filler (kept, not guessed)."""
    opt_out: bool = False
    opt_in: bool = False
    skip: bool = False

    @property
    def has_answers(self) -> bool:
        return bool(self.numbered or self.ordered or self.to_all)

    @property
    def is_empty(self) -> bool:
        """Nothing usable: no answer, comment or command."""
        return not (self.has_answers or self.comment or self.opt_out or self.opt_in or self.skip)


def looks_like_request(text: str) -> bool:
    """True when ``text`` reads as a new instruction ("could you bring me ...")."""
    return bool(_REQUEST.match(text.strip()))


def word_count(text: str) -> int:
    return len(re.findall(r"[^\W\d_]{2,}", text))


_KEY_ROWS = ("qwertyuiop", "asdfghjkl", "zxcvbnm")
_KEY_RUNS = frozenset(
    run
    for row in _KEY_ROWS
    for line in (row, row[::-1])
    for length in range(3, len(line) + 1)
    for start in range(len(line) - length + 1)
    for run in (line[start : start + length],)
)


def is_keyboard_mash(word: str) -> bool:
    """A word typed by sliding along the keyboard ("asdf", "qwerty", "asdfasdf") or holding
    one key ("aaaa"): each part a run of 3+ neighbouring keys of one row, either way."""
    letters = word.lower()
    if len(letters) >= 3 and len(set(letters)) == 1:
        return True

    @functools.cache
    def splits(start: int) -> bool:  # letters[start:] is a sequence of runs
        if start == len(letters):
            return True
        return any(
            letters[start:end] in _KEY_RUNS and splits(end)
            for end in range(start + 3, len(letters) + 1)
        )

    return len(letters) >= 3 and splits(0)


def says_something(text: str) -> bool:
    """Whether ``text`` holds a word a person wrote to say something (not keyboard mash)."""
    return any(not is_keyboard_mash(w) for w in re.findall(r"[^\W\d_]{2,}", text))


def parse_reply(text: str) -> ParsedReply:
    """Read one message; never raises, whatever the text."""
    stripped = text.strip()
    if _OPT_OUT.search(stripped):
        return ParsedReply(opt_out=True)
    if _OPT_IN.search(stripped):
        return ParsedReply(opt_in=True)
    if _SKIP.match(stripped):
        return ParsedReply(skip=True)
    answer_part, comment = _split_comment(stripped)
    compact = answer_part.lower().replace(" ", "")
    if _COMPACT.match(compact):
        return ParsedReply(ordered=tuple(_WORDS[c] for c in compact), comment=comment)
    return _read_answers(answer_part, comment)


def _split_comment(text: str) -> tuple[str, str | None]:
    mark = _COMMENT_MARK.search(text)
    if mark is None:
        return text, None
    comment = text[mark.end() :].strip()
    return text[: mark.start()].strip(), comment or None


def _read_answers(text: str, comment: str | None) -> ParsedReply:
    normalised = text.lower()
    if len(normalised) != len(text):  # a few letters change length when lower-cased
        normalised = text.casefold() if len(text.casefold()) == len(text) else text
    for pattern, letter in _PHRASES:
        normalised = pattern.sub(functools.partial(_padded, letter), normalised)
    tokens = [m for m in _TOKEN.finditer(normalised) if m.group().strip()]
    numbered: dict[int, Choice] = {}
    ordered: list[Choice] = []
    unclear: list[tuple[int, str]] = []
    all_at: int | None = None
    pending_number: int | None = None
    last_answer = -1  # index of the token holding the last answer
    for i, match in enumerate(tokens):
        token = match.group()
        number = _question_number(token)
        if number is not None:
            pending_number = number
            continue
        choice = _WORDS.get(token)
        if choice is not None:
            if pending_number is not None:
                numbered[pending_number] = choice
                pending_number = None
            else:
                ordered.append(choice)
            last_answer = i
            continue
        if token in _ALL_WORDS and all_at is None:
            all_at = i
        if token in _FILLERS or not any(c.isalnum() for c in token):
            continue
        unclear.append((i, token))

    # Words after the last answer are a comment ("yes yes no yes, it was quick"); words
    # between answers stay unclear.
    has_tail = any(i > last_answer for i, _ in unclear)
    # "all yes" / "yes to all", but not the "all" of a comment ("yes, all fine").
    says_all = all_at is not None and (all_at < last_answer or not has_tail)
    if last_answer >= 0 and has_tail:
        tail = text[tokens[last_answer].end() :].strip(" ,;.:-–—!")
        comment = f"{tail} {comment}" if comment else tail
        unclear = [(i, u) for i, u in unclear if i < last_answer]

    to_all: Choice | None = None
    if says_all and len(set(ordered)) == 1:
        to_all, ordered = ordered[0], []
    return ParsedReply(
        numbered=numbered,
        ordered=tuple(ordered),
        to_all=to_all,
        comment=comment,
        unclear=tuple(u for _, u in unclear),
    )


def _padded(letter: str, match: re.Match[str]) -> str:
    return letter.ljust(len(match.group()))


def _question_number(token: str) -> int | None:
    digits = token.removeprefix("q")
    if not digits.isdigit():
        return None
    number = int(digits)
    return number if 1 <= number <= QUESTION_COUNT else None
