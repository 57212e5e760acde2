"""On start-up, before anything else restarts: no finished code opens the locker again.

A code may open the locker after a restart only when the journal says its hand-over is still
to happen: its instruction is unfinished, its last checkpoint lists the code as issued (not
scanned, used or revoked) or the ledger lists it as minted by a send (one the process died in
before the checkpoint), the code ledger holds no end for it, and it has not expired.
Every other code the service can name (the payloads in the code book and in the simulated
people's hands, and the codes of instructions that ended within one code lifetime) is
journaled as revoked and withdrawn at the lock: an in-process lock, which forgot everything
with the process, learns it as revoked; a networked one is asked to revoke it (it may have
missed the revocation when the process died). An in-process lock is armed again with the
live codes only.
"""

from __future__ import annotations

import logging
from collections.abc import Iterable
from dataclasses import dataclass, field

from assistantx.adapters.lock.protocol.codes import CodeClaims, unseal
from assistantx.adapters.lock.protocol.keys import Keyring
from assistantx.core.errors import InvalidCodeError, LockError
from assistantx.core.ports.lock import Locker
from assistantx.service.code_ledger import CodeLedger
from assistantx.sim.lock.local import LocalLocker
from assistantx.store.journal import FINAL_STATUSES, InstructionRecord, Journal

logger = logging.getLogger(__name__)

RECENT_INSTRUCTIONS = 200  # ended instructions looked at for codes still live at a lock


@dataclass
class Settled:
    """What the start-up left live (payloads people may keep) and what it withdrew."""

    live: set[str] = field(default_factory=set)
    withdrawn: set[str] = field(default_factory=set)  # code ids


@dataclass
class _Dead:
    code_id: str
    until: float  # when the code expires anyway


async def settle_codes(
    journal: Journal,
    ledger: CodeLedger,
    locker: Locker,
    keyring: Keyring,
    payloads: Iterable[str],
    now: float,
    lifetime_s: float,
) -> Settled:
    """Withdraw every finished code (journal first, then the lock); arm an in-process lock
    with the live ones. Call it once the lock is connected and before the assistant starts."""
    records: dict[str, InstructionRecord | None] = {}

    def record(instruction_id: str) -> InstructionRecord | None:
        if instruction_id not in records:
            records[instruction_id] = journal.instruction(instruction_id)
        return records[instruction_id]

    settled = Settled()
    dead: dict[str, _Dead] = {}
    live: dict[str, tuple[CodeClaims, str]] = {}
    for payload in set(payloads):
        try:
            claims = unseal(payload, keyring)
        except InvalidCodeError:
            continue  # under a key we no longer hold: no lock of ours accepts it
        if claims.expires_at <= now:
            continue
        if _open(record(claims.instruction_id), claims.code_id, ledger):
            live[claims.code_id] = (claims, payload)
        else:
            dead[claims.code_id] = _Dead(claims.code_id, claims.expires_at)
    for record_ in _recently_ended(journal, now - lifetime_s):
        for code in record_.stm.embodied.codes if record_.stm else []:
            if code.code_id not in live and code.code_id not in dead:
                if code.state == "issued" and ledger.ended(code.code_id) is None:
                    dead[code.code_id] = _Dead(code.code_id, record_.updated_at + lifetime_s)

    await ledger.retire(d.code_id for d in dead.values())
    for d in dead.values():
        if await _withdraw(locker, d):
            settled.withdrawn.add(d.code_id)
    for claims, payload in live.values():
        if isinstance(locker, LocalLocker):
            try:
                locker.controller.provision(payload)
            except LockError as exc:
                logger.info("code %s of %s not armed again: %s", claims.code_id, claims.person, exc)
                continue
        settled.live.add(payload)
    if dead or live:
        logger.info(
            "codes at start-up: %d withdrawn, %d still open for unfinished hand-overs",
            len(settled.withdrawn),
            len(settled.live),
        )
    return settled


def _open(record: InstructionRecord | None, code_id: str, ledger: CodeLedger) -> bool:
    """Whether the journal says ``code_id``'s hand-over is still to happen."""
    if record is None or record.status in FINAL_STATUSES or record.stm is None:
        return False
    if ledger.ended(code_id) is not None:
        return False
    if ledger.was_minted(code_id):
        # Minted by a send the process died in (its checkpoint not yet written): the step
        # runs again and re-uses it if its message went out, or withdraws it.
        return True
    return any(c.code_id == code_id and c.state == "issued" for c in record.stm.embodied.codes)


def _recently_ended(journal: Journal, since: float) -> list[InstructionRecord]:
    ended: list[InstructionRecord] = []
    for summary in journal.instructions(limit=RECENT_INSTRUCTIONS):
        if summary.updated_at >= since and summary.status in FINAL_STATUSES:
            full = journal.instruction(summary.id)
            if full is not None:
                ended.append(full)
    return ended


async def _withdraw(locker: Locker, dead: _Dead) -> bool:
    if isinstance(locker, LocalLocker):
        locker.controller.retire(dead.code_id, dead.until)
        return True
    try:
        await locker.revoke(dead.code_id)
    except LockError as exc:
        # Most often "no active code": it was used, revoked or expired at the lock already.
        logger.info("code %s not revoked at the lock: %s", dead.code_id, exc)
        return False
    return True
