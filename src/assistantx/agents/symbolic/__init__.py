"""The embedded default reasoner: deterministic Perception, Planning, Decision and Reflection.

It understands instructions with rules over the office's own vocabulary, asks when it is not
sure, plans the canonical action sequences of docs/task-semantics.md, and needs no LLM and no
network. ``build_factory(office, settings)`` is what ``assistantx.agents.registry`` loads for
``--reasoner symbolic``.
"""

from assistantx.agents.symbolic.reading.parser import InstructionParser, Task, TaskFrame
from assistantx.agents.symbolic.reasoner import SymbolicReasoner, build_factory

__all__ = ["InstructionParser", "SymbolicReasoner", "Task", "TaskFrame", "build_factory"]
