"""The embedded default reasoner: deterministic Perception, Planning, Decision and Reflection.

It understands instructions with rules over the office's own vocabulary, asks when it is not
sure, plans the canonical action sequences of docs/task-semantics.md, and needs no LLM and no
network. ``build_factory(office, settings)`` is what ``assistantx.agents.registry`` loads for
``--reasoner symbolic``.

Names are loaded from their modules on first use (PEP 562): the runtime imports one small
submodule (``answers``, for consent replies) at start, and with it this package; the reader
and its language tools (lemminflect, ~0.4 CPU-s of imports) then load when the reasoner is
built, after the service is ready (``service.reasoner_warmup``).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from assistantx.core.lazy import exports

if TYPE_CHECKING:
    from assistantx.agents.symbolic.reading.parser import InstructionParser, Task, TaskFrame
    from assistantx.agents.symbolic.reasoner import SymbolicReasoner, build_factory

_WHERE = {
    "InstructionParser": "assistantx.agents.symbolic.reading.parser",
    "Task": "assistantx.agents.symbolic.reading.parser",
    "TaskFrame": "assistantx.agents.symbolic.reading.parser",
    "SymbolicReasoner": "assistantx.agents.symbolic.reasoner",
    "build_factory": "assistantx.agents.symbolic.reasoner",
}


__getattr__ = exports(__name__, _WHERE)


__all__ = ["InstructionParser", "SymbolicReasoner", "Task", "TaskFrame", "build_factory"]
