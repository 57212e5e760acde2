"""``assistantx lock-sim``: the lock emulator as its own process; ``assistantx lock-keys``:
make and rotate key files.

Keys come from ``--key-file`` (or ``ASSISTANTX_LOCK_KEY_FILE``), else from the shared secret
in ``ASSISTANTX_LOCK_SHARED_KEY``, else from the key file kept in ``ASSISTANTX_DATA_DIR`` (made
there by whichever of ``lock-sim`` and ``serve`` starts first): the one rule of
``assistantx.adapters.lock.protocol.keys.load_lock_keys``, so a lock-sim and a service on one
data folder agree with no key configured. Rotation without downtime::

    assistantx lock-keys rotate keys.json   # new current key, previous one kept
    kill -HUP <lock-sim pid>                # the lock now accepts both keys
    (restart or reload the assistant)       # it now seals new codes with the new key
"""

from __future__ import annotations

import argparse
import asyncio
import contextlib
import os
import signal
from pathlib import Path

from assistantx.adapters.lock.protocol.keys import KeyringError, LockKeys, load_lock_keys, new_key
from assistantx.adapters.lock.protocol.link import LinkTimeouts
from assistantx.core.clock import WallClock
from assistantx.core.settings import Settings
from assistantx.service.data_dir import LOCK_KEYS_FILE, ensure_data_dir
from assistantx.sim.lock.controller import LockController
from assistantx.sim.lock.server import LockServer


def register(sub: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    # Defaults from Settings are resolved when the command runs, not when the parser is built,
    # so a bad environment variable only affects the command that uses it.
    sim = sub.add_parser("lock-sim", help="run the smart lock emulator (TCP server)")
    sim.add_argument("--host", default="127.0.0.1", help="address to listen on")
    sim.add_argument("--port", type=int, help="default ASSISTANTX_LOCK_PORT; 0 picks a free one")
    sim.add_argument("--lock-id", help="default ASSISTANTX_LOCK_ID")
    sim.add_argument(
        "--key-file", type=Path, help="default: the keys `assistantx serve` uses on the data folder"
    )
    sim.add_argument(
        "--handshake-timeout",
        type=float,
        default=2.0,
        metavar="S",
        help="an unauthenticated connection gets this long to authenticate",
    )
    sim.add_argument("--frame-timeout", type=float, default=5.0, metavar="S")
    sim.add_argument("--idle-timeout", type=float, default=30.0, metavar="S")
    sim.add_argument("--max-connections", type=int, default=32, help="authenticated sessions")
    sim.add_argument(
        "--max-pending",
        type=int,
        default=256,
        help="connections still authenticating, in all (the oldest is evicted beyond it)",
    )
    sim.add_argument(
        "--max-pending-per-peer",
        type=int,
        default=64,
        help="connections still authenticating from one address (the oldest is evicted)",
    )
    sim.add_argument("--event-log", type=int, default=1024, help="events kept for resuming")
    sim.set_defaults(func=run_lock_sim)

    keys = sub.add_parser("lock-keys", help="create or rotate a lock key file")
    keys.add_argument("action", choices=["new", "rotate"])
    keys.add_argument("file", type=Path)
    keys.set_defaults(func=run_lock_keys)


def _load_keys(key_file: Path | None, settings: Settings) -> LockKeys:
    secret = settings.lock_shared_key
    return load_lock_keys(
        key_file=key_file or settings.lock_key_file,
        secret=secret.get_secret_value() if secret is not None else None,
        fallback_file=ensure_data_dir(settings.data_dir) / LOCK_KEYS_FILE,
    )


def run_lock_sim(args: argparse.Namespace) -> int:
    if min(args.max_connections, args.max_pending, args.max_pending_per_peer) < 1:
        print("lock-sim: --max-connections and --max-pending* must be at least 1")
        return 2
    try:
        settings = Settings()
        args.port = settings.lock_port if args.port is None else args.port
        args.lock_id = args.lock_id or settings.lock_id
        keys = _load_keys(args.key_file, settings)
        if args.key_file is None and settings.lock_shared_key is None:
            # SIGHUP reloads the file serve and lock-sim share (the data folder's by default).
            args.key_file = settings.lock_key_file or settings.data_dir / LOCK_KEYS_FILE
        timeouts = LinkTimeouts(
            handshake_s=args.handshake_timeout,
            frame_s=args.frame_timeout,
            idle_s=args.idle_timeout,
        )
    except (KeyringError, ValueError, OSError) as exc:
        print(f"lock-sim: {exc}")
        return 2
    return asyncio.run(_serve(args, keys, timeouts))


async def _serve(args: argparse.Namespace, keys: LockKeys, timeouts: LinkTimeouts) -> int:
    controller = LockController(
        args.lock_id, keys.codes, WallClock(), event_log_size=args.event_log
    )
    key_file: Path | None = args.key_file
    server = LockServer(
        controller,
        keys.link_key,
        host=args.host,
        port=args.port,
        timeouts=timeouts,
        max_connections=args.max_connections,
        max_pending=args.max_pending,
        max_pending_per_peer=args.max_pending_per_peer,
        reload_keys=(lambda: LockKeys.from_file(key_file).codes) if key_file else None,
    )
    try:
        host, port = await server.start()
    except OSError as exc:
        print(f"lock-sim: cannot listen on {args.host}:{args.port}: {exc}")
        return 1
    stopping = asyncio.Event()
    loop = asyncio.get_running_loop()
    for signum in (signal.SIGINT, signal.SIGTERM):
        with contextlib.suppress(NotImplementedError):
            loop.add_signal_handler(signum, stopping.set)
    if key_file is not None and hasattr(signal, "SIGHUP"):
        loop.add_signal_handler(signal.SIGHUP, server.reload_keys_logged)
    print(f"lock-sim: lock {args.lock_id} listening on {host}:{port}", flush=True)
    try:
        await stopping.wait()
    finally:
        await server.stop()
    print("lock-sim: stopped", flush=True)
    return 0


def run_lock_keys(args: argparse.Namespace) -> int:
    path: Path = args.file
    if args.action == "new":
        if path.exists():
            print(f"lock-keys: {path} exists; not overwriting it")
            return 1
        keys = LockKeys.generate()
    else:
        try:
            keys = LockKeys.from_file(path)
        except KeyringError as exc:
            print(f"lock-keys: {exc}")
            return 1
        next_id = f"k{1 + max(_number(k) for k in keys.codes.key_ids())}"
        keys.codes.rotate(next_id, new_key())
    _write_privately(path, keys.to_json() + "\n")
    print(f"lock-keys: {path}: current key {keys.codes.current_id}, {keys.codes.key_ids()}")
    return 0


def _number(key_id: str) -> int:
    digits = key_id.lstrip("k")
    return int(digits) if digits.isdigit() else 0


def _write_privately(path: Path, text: str) -> None:
    # Owner-only from the first byte, and atomic: a lock reloading on SIGHUP never reads
    # half a file.
    temporary = path.with_name(f".{path.name}.tmp")
    fd = os.open(temporary, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o600)
    with os.fdopen(fd, "w", encoding="utf-8") as handle:
        handle.write(text)
    temporary.replace(path)
