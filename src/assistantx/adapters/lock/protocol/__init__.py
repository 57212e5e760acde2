"""The smart lock: one-time QR codes, the locker's logic, and its TCP link.

Knows nothing of agents. ``codes`` seals and draws codes, ``controller`` is the locker with
no I/O, ``frames``/``link`` speak the wire protocol, ``server`` is the emulator and
``client`` the assistant's side of the link.
"""

from assistantx.adapters.lock.protocol.codes import CodeClaims, CodeIssuer, render_png, seal, unseal
from assistantx.adapters.lock.protocol.controller import (
    EventBacklog,
    LockController,
    RejectReason,
    ScanResult,
)
from assistantx.adapters.lock.protocol.keys import Keyring, KeyringError, LockKeys

__all__ = [
    "CodeClaims",
    "CodeIssuer",
    "EventBacklog",
    "Keyring",
    "KeyringError",
    "LockController",
    "LockKeys",
    "RejectReason",
    "ScanResult",
    "render_png",
    "seal",
    "unseal",
]
