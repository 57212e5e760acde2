"""The types of the screen tests' fixtures (``conftest``): a message read into lexed pieces,
and one rule's finding on the first piece of a message."""

from __future__ import annotations

from collections.abc import Callable

from assistantx.agents.symbolic.reading.screen.findings import Finding
from assistantx.agents.symbolic.reading.screen.pieces import Message
from assistantx.agents.symbolic.reading.screen.rules import Rule

Read = Callable[[str], Message]
Judge = Callable[[Rule, str, str], Finding | None]
