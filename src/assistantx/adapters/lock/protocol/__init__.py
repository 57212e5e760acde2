"""The smart lock: one-time QR codes, the locker's logic, and its TCP link.

Knows nothing of agents. ``codes`` seals and draws codes, ``frames``/``link`` speak the wire
protocol and ``client`` is the assistant's side of the link. The locker itself (its logic and
the TCP emulator) is simulated in :mod:`assistantx.sim.lock`.
"""

from assistantx.adapters.lock.protocol.codes import CodeClaims, CodeIssuer, render_png, seal, unseal
from assistantx.adapters.lock.protocol.keys import Keyring, KeyringError, LockKeys

__all__ = [
    "CodeClaims",
    "CodeIssuer",
    "Keyring",
    "KeyringError",
    "LockKeys",
    "render_png",
    "seal",
    "unseal",
]
