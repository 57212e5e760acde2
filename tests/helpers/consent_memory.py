"""Short-term memory for consent checks in tests: a request, and people who answered."""

from __future__ import annotations

from assistantx.core.dialogue import DialogueTurn
from assistantx.core.ports.messenger import ChatRef
from assistantx.memory.short_term import ShortTermMemory


def memory(requester: str, text: str) -> ShortTermMemory:
    return ShortTermMemory.begin("i-1", requester, text, reasoner="t", started_at=0)


def exchange(
    person: str, question: str, answer: str, *, time: int = 0, question_id: str = "q0"
) -> list[DialogueTurn]:
    """``question`` asked in ``person``'s own chat at ``time``, and their ``answer`` to it
    the next second."""
    dm = ChatRef(kind="dm", id=person)
    return [
        DialogueTurn(
            time=time,
            direction="out",
            chat=dm,
            person=person,
            text=question,
            question_id=question_id,
        ),
        DialogueTurn(
            time=time + 1,
            direction="in",
            chat=dm,
            person=person,
            text=answer,
            in_reply_to=question_id,
        ),
    ]


def answered(stm: ShortTermMemory, *people: str) -> None:
    """Each person was asked in their own chat and said yes."""
    for n, person in enumerate(people):
        stm.dialogue += exchange(person, "Could you?", "sure", time=2 * n, question_id=f"q{n}")
