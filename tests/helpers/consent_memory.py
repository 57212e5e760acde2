"""Short-term memory for consent checks in tests: a request, and people who answered."""

from __future__ import annotations

from assistantx.core.dialogue import DialogueTurn
from assistantx.core.ports.messenger import ChatRef
from assistantx.memory.short_term import ShortTermMemory


def memory(requester: str, text: str) -> ShortTermMemory:
    return ShortTermMemory.begin("i-1", requester, text, reasoner="t", started_at=0)


def answered(stm: ShortTermMemory, *people: str) -> None:
    """Each person was asked in their own chat and said yes."""
    for n, person in enumerate(people):
        dm = ChatRef(kind="dm", id=person)
        stm.dialogue += [
            DialogueTurn(
                time=2 * n,
                direction="out",
                chat=dm,
                person=person,
                text="Could you?",
                question_id=f"q{n}",
            ),
            DialogueTurn(
                time=2 * n + 1,
                direction="in",
                chat=dm,
                person=person,
                text="sure",
                in_reply_to=f"q{n}",
            ),
        ]
