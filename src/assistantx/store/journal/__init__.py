"""The durable journal of the service (SQLite, WAL)."""

from assistantx.core.errors import JournalError
from assistantx.store.journal.store import (
    FINAL_STATUSES,
    MAX_SEQ,
    STATUSES,
    ChatSummary,
    EventRecord,
    InstructionRecord,
    Journal,
    MessageRecord,
    Status,
)

__all__ = [
    "FINAL_STATUSES",
    "MAX_SEQ",
    "STATUSES",
    "ChatSummary",
    "EventRecord",
    "InstructionRecord",
    "Journal",
    "JournalError",
    "MessageRecord",
    "Status",
]
