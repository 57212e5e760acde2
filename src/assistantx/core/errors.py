"""The error tree of AssistantX.

    AssistantXError
    ├── OfficeError                 a bad office file (names the file, the entry and the problem)
    ├── MapError                    a bad map_server map or anchors file
    ├── GroundingError              an action argument that does not resolve in memory
    │   ├── UnknownNameError        nothing matches the name
    │   └── AmbiguousNameError      several things match the name
    ├── ActionError                 an action that is invalid in the current state
    ├── AdapterError                an outside part (messenger, robot, lock) failed
    │   ├── MessengerError
    │   │   └── UnreachableContactError  no account or room for that person or group
    │   ├── RobotError
    │   │   ├── UnreachableError    goal outside the map, inside an obstacle, or cut off
    │   │   ├── BlockedError        the path became blocked while driving
    │   │   │   └── DoorClosedError the only way runs through a doorway that is shut
    │   │   └── LocalizationLostError
    │   └── LockError
    │       ├── LockConnectionError the lock cannot be reached, or the link dropped
    │       │   └── LockTimeoutError  no answer within the timeout
    │       ├── LockAuthError       the handshake failed: wrong shared key or a fake peer
    │       ├── LockProtocolError   a malformed, oversized or unexpected frame
    │       ├── LockCommandError    the lock refused a command (door state, unknown code)
    │       └── InvalidCodeError    a QR payload that is malformed, forged or under an unknown key
    ├── ReasonerError               an agent could not produce a valid output
    │   ├── ModelOutputError (ValueError)  one model answer is unusable; fed back, retried
    │   └── ModelBehaviorError      the model kept producing invalid output after retries
    ├── LLMError                    the model server failed (HTTP, timeout) after retries
    ├── JournalError                the service's journal file is unusable
    │   └── LeaseLostError          a write or renewal under a lease another holder took over
    ├── PromptError (ValueError)    a prompt template file that is malformed, or a bad render
    └── DatasetError                a bad base-instruction or task file (names file and entry)

Low-level errors are translated at the boundary with ``raise ... from exc``. The text of a
GroundingError is written so it can be fed back to a language model as-is.
"""

from __future__ import annotations

from collections.abc import Sequence


class AssistantXError(Exception):
    """Base of every error raised by AssistantX."""


class OfficeError(AssistantXError):
    """An office file that cannot be loaded."""

    def __init__(self, path: str, entry: str, problem: str) -> None:
        self.path = path
        self.entry = entry
        self.problem = problem
        super().__init__(f"{path}: {entry}: {problem}")


class MapError(AssistantXError):
    """A map or anchors file that cannot be loaded (names the file and the problem)."""


class GroundingError(AssistantXError):
    """An action argument that does not resolve to exactly one thing in memory."""

    def __init__(self, kind: str, name: str, message: str, candidates: list[str] | None = None):
        self.kind = kind
        self.name = name
        self.candidates = candidates or []
        super().__init__(message)


class UnknownNameError(GroundingError):
    """Nothing in memory matches the name."""


class AmbiguousNameError(GroundingError):
    """Several things in memory match the name."""


class ActionError(AssistantXError):
    """An action that cannot be carried out in the current state."""


class AdapterError(AssistantXError):
    """An outside part failed."""


class MessengerError(AdapterError):
    """The messenger could not deliver or receive."""


class MessengerClosedError(MessengerError):
    """The messenger's connection was closed (the service is stopping): the work in hand is
    no message's fault and is to be taken again after a restart, never skipped."""


class UnreachableContactError(MessengerError):
    """The messenger has no way to reach this person or group at all (no account, no room):
    trying again cannot help, so the loop records the person as unreachable."""


class RobotError(AdapterError):
    """The robot base could not complete a motion."""


class UnreachableError(RobotError):
    """The goal lies outside the map, inside an obstacle, or cannot be reached."""


class BlockedError(RobotError):
    """The path became blocked while driving."""


class DoorClosedError(BlockedError):
    """Every way to the goal runs through a doorway (a gap in the map's walls) that something
    now shuts: most likely a closed door."""


class LocalizationLostError(RobotError):
    """The localizer lost track of the robot's pose."""


class LockError(AdapterError):
    """The locker could not carry out a command."""


class LockConnectionError(LockError):
    """The lock cannot be reached, or the link to it dropped."""


class LockTimeoutError(LockConnectionError):
    """The lock gave no answer within the timeout."""


class LockAuthError(LockError):
    """The link handshake failed: a wrong shared key, or a peer that does not hold it."""


class LockProtocolError(LockError):
    """A malformed, oversized or unexpected frame on the lock link."""


class LockCommandError(LockError):
    """The lock refused a command; ``kind`` names why (e.g. ``door_closed``, ``unknown_code``)."""

    def __init__(self, kind: str, message: str) -> None:
        self.kind = kind
        super().__init__(message)


class InvalidCodeError(LockError):
    """A QR payload that is malformed, forged, or encrypted under a key the keyring lacks."""

    def __init__(self, reason: str, message: str) -> None:
        self.reason = reason
        super().__init__(message)


class ReasonerError(AssistantXError):
    """An agent could not produce a valid output."""


class ModelOutputError(ReasonerError, ValueError):
    """One answer of the model is unusable: it does not parse, fails the output schema, or
    names a person, place or action that memory does not know.

    This is the ONLY error a structured call feeds back to the model ("your answer could not
    be used: ...") and retries; its text is written for the model. Any other exception raised
    while checking an answer (KeyError, TypeError, a plain ValueError) is a bug in our own
    checks: it propagates and is never shown to the model as if it were the model's fault.
    """


class ModelBehaviorError(ReasonerError):
    """The model kept producing invalid output after the allowed retries.

    ``last_error`` is the problem fed back after the last try; ``attempts`` holds one record
    per try (the LLM layer stores its ``Attempt`` objects there).
    """

    def __init__(
        self, message: str, *, last_error: str = "", attempts: Sequence[object] = ()
    ) -> None:
        self.last_error = last_error
        self.attempts = tuple(attempts)
        super().__init__(message)


class LLMError(AssistantXError):
    """The model server failed after retries."""


class JournalError(AssistantXError):
    """The journal database is unusable (another schema version, a corrupt file)."""


class LeaseLostError(JournalError):
    """A write carried a fencing token that is no longer the office's (another replica took
    the office over), or a renewal came after the lease was taken or released."""


class PromptError(AssistantXError, ValueError):
    """A prompt template that cannot be loaded or rendered; names the file."""

    def __init__(self, path: str, problem: str) -> None:
        self.path = path
        self.problem = problem
        super().__init__(f"{path}: {problem}")


class DatasetError(AssistantXError):
    """A base-instruction or task file that cannot be loaded (names the file and the entry)."""
