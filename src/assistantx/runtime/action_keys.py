"""The idempotency key of an action within its step, from what the action does.

A step cut short by a crash runs again under the same index after the restart, but its
decision is taken again from the checkpoint, which may already hold the effect of an action
done before the crash (the robot already at Lee's desk): the replayed decision can then leave
that action out, and every later action moves up one place. A key by position ("the second
action of step 5") would then name a different action, and a code sent before the crash would
go out again under a new key. A key from the step and the action itself (its kind and every
argument: whom, what item, which words) is the same whatever comes before it in the decision;
the same action twice in one step is told apart by how many came before it.
"""

from __future__ import annotations

import hashlib
from collections import Counter

from assistantx.core.actions import Action


class StepKeys:
    """Hands out the key of each action of one step, in the order they run."""

    def __init__(self, step_index: int) -> None:
        self.step_index = step_index
        self._seen: Counter[str] = Counter()

    def next(self, action: Action) -> str:
        signature = action.signature()
        repeat = self._seen[signature]
        self._seen[signature] += 1
        digest = hashlib.sha256(signature.encode()).hexdigest()[:16]
        key = f"s{self.step_index}.{action.type}.{digest}"
        return key if repeat == 0 else f"{key}.{repeat}"
