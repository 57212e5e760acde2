"""Who does the work: the frames' tasks checked against who can do them, once the frames are
read and the screen has decided, before the judge.

- ``without_toolless``: "scanned and stamped" where nobody has a seal: told (or asked) before
  anything moves;
- ``with_named_maker``: "could Wang make one? I need a coffee": Wang makes it only if Wang
  keeps a machine that makes it; else said, and asked before the keepers make it;
- ``with_named_doer``: "could Wang print my file?": the same for a service done on the
  requester's thing;
- ``keepers_work``: "need an ABV on my sample, can zosia run it": where nothing is to be done
  yet and a question is left, the work of the keeper's facility on the requester's thing,
  said plainly for the reader to read again (the need's noun named none).
"""

from __future__ import annotations

from assistantx.agents.symbolic.reading.keeper_asked_work import keeper_asked_work
from assistantx.agents.symbolic.reading.lexicon import Lexed
from assistantx.agents.symbolic.reading.named_doer import with_named_doer
from assistantx.agents.symbolic.reading.named_maker import with_named_maker
from assistantx.agents.symbolic.reading.toolless_parts import without_toolless
from assistantx.core.office import Office
from assistantx.core.task_schema import TaskFrame

__all__ = ["keepers_work", "with_doers"]


def with_doers(
    office: Office, whole: Lexed, frame: TaskFrame, requester: str, *, confirmed: bool
) -> TaskFrame:
    """``frame`` with its doers checked (``whole``: the whole message as the lexicon read it;
    ``confirmed``: the requester already said yes to the restated reading)."""
    frame = without_toolless(office, frame, requester, confirmed=confirmed)
    frame = with_named_maker(office, whole, frame, requester, confirmed=confirmed)
    return with_named_doer(office, whole, frame, requester, confirmed=confirmed)


def keepers_work(office: Office, whole: Lexed, frame: TaskFrame, requester: str) -> str | None:
    """The message said as the work of the keeper's facility on the requester's thing, to be
    read again, where ``frame`` has nothing to do and a question left; else None."""
    if frame.tasks or frame.question is None:
        return None
    return keeper_asked_work(office, whole, requester)
