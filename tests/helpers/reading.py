"""The symbolic reader on a test office, as the reader's tests set it up: one parser an office
a process (building one reads the whole office; parsing changes nothing in it, so tests may
share it), and a request's frame as a colleague of that office says it."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Protocol

from assistantx.agents.symbolic import InstructionParser
from assistantx.core import task_kinds
from assistantx.core.office import Office
from assistantx.core.task_schema import TaskFrame

OfficeOf = Callable[[], Office]  # a test office's builder (helpers.hostel.hostel...)

_PARSERS: dict[OfficeOf, tuple[tuple[task_kinds.KindSpec, ...], InstructionParser]] = {}


def parser_for(office: OfficeOf) -> InstructionParser:
    """The parser of ``office()``, built once (again if a test changed the task kinds)."""
    kinds = task_kinds.kinds()
    kept = _PARSERS.get(office)
    if kept is None or kept[0] != kinds:
        kept = _PARSERS[office] = (kinds, InstructionParser(office()))
    return kept[1]


class ReadFrame(Protocol):
    def __call__(self, text: str, who: str = ...) -> TaskFrame: ...


class ReadAnswered(Protocol):
    def __call__(self, text: str, answers: Sequence[str] = ...) -> TaskFrame: ...


def frame_reader(office: OfficeOf, requester: str) -> ReadFrame:
    """``text`` read as ``who`` (``requester`` unless named) says it in ``office()``."""

    def frame(text: str, who: str = requester) -> TaskFrame:
        return parser_for(office).parse(text, who)

    return frame


def answered_reader(office: OfficeOf, requester: str) -> ReadAnswered:
    """``text`` read as ``requester`` says it, with ``answers`` to the questions it raises."""

    def frame(text: str, answers: Sequence[str] = ()) -> TaskFrame:
        return parser_for(office).parse_with_answers(text, requester, list(answers))

    return frame
