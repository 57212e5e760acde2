"""``assistantx serve [--host H] [--port P]``: the REST API, live events and the dashboard.

Start-up order matters when a second process is started by mistake: the data folder's lock
first, then the port, and only then the journal (resuming the running instructions). A second
``serve`` on the same folder or port exits with a one-line error and has changed nothing.
"""

from __future__ import annotations

import argparse
import gc
import signal
import socket
import sys
from typing import TYPE_CHECKING

from assistantx.core.settings import Settings

if TYPE_CHECKING:
    from assistantx.service.offices.directory import Offices


def register(sub: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    p = sub.add_parser(
        "serve",
        help="run the assistant as a service (REST API + dashboard)",
        description=(
            "Serve one office (ASSISTANTX_OFFICE) or several: ASSISTANTX_OFFICES=deployment.yaml"
            " lists them (id, name, and each office's own settings: office, map, map_anchors,"
            " lock_port, matrix_config, tokens ...); each is served at /v1/offices/ID/..., the"
            " first also at today's paths. With ASSISTANTX_DATABASE_URL several serve"
            " processes share the offices, each under its own lease. See README, Configuration."
        ),
    )
    p.add_argument("--host", default=None, help="bind address (default: ASSISTANTX_HOST)")
    p.add_argument("--port", type=int, default=None, help="port (default: ASSISTANTX_PORT)")
    p.set_defaults(func=_serve)


def _serve(args: argparse.Namespace) -> int:
    # Start-up builds objects that live as long as the process (modules, classes, the
    # routes' schemas, the office): the collector walked them some 270 times before ready,
    # a fifth of the CPU time to ready (0.16 of 0.85 CPU-s), and found little to free
    # (about 1,600 objects, ~1 MB, now kept: frozen at ready with the rest, once). Off
    # until ready, where the heap is frozen (announce) and the collector is on again.
    gc.disable()
    # before any thread allocates: a thread's arena is chosen at its first malloc
    from assistantx.service.malloc_arenas import limit_arenas

    limit_arenas()
    try:
        return _serve_collector_off(args)
    finally:
        gc.enable()  # also when the start failed before ready


def _serve_collector_off(args: argparse.Namespace) -> int:
    import asyncio

    from assistantx.nav import disk_cache
    from assistantx.service.app import create_app
    from assistantx.service.collector import SurvivorFreezer
    from assistantx.service.datalock import DataDirBusyError, DataDirLock
    from assistantx.service.offices.deployment import DeploymentError, load_deployment
    from assistantx.service.runtime import MAP_CACHE_DIR
    from assistantx.service.server import service_server
    from assistantx.service.turns import turns_of

    settings = Settings()
    # The map's derived arrays are kept by content hash from the first use on, the check of
    # the robot's files below included (it builds the costmap and planner the service uses);
    # keyed by content, one folder serves every office of a deployment.
    disk_cache.use_directory(settings.data_dir / MAP_CACHE_DIR)
    try:
        offices = load_deployment(settings)
    except DeploymentError as exc:
        print(f"assistantx serve: {exc}", file=sys.stderr)
        return 2
    for office in offices:  # every office's map and anchors, before anything binds
        problem = _robot_files_problem(office.settings)
        if problem is not None:
            print(f"error: {problem}")
            return 2
    host = args.host or settings.host
    port = args.port if args.port is not None else settings.port
    shown = "127.0.0.1" if host in ("0.0.0.0", "::") else host

    def announce(offices: Offices) -> None:
        # What start-up built lives as long as the process: out of the collector's sight, a
        # full collection no longer walks it (shorter pauses of the event loop), and neither
        # do the collections of the interpreter's exit, which took about a CPU-second of
        # every stop (perf: two thirds of the stop in gc_collect_main).
        gc.freeze()
        # From now on what survives a full collection is frozen too, so a full collection
        # walks what came since the last one, not every running instruction's memory; the
        # loop runs one every second, between requests (paced), so each walks a second's.
        freezer = SurvivorFreezer()
        freezer.install()
        freezer.pace(asyncio.get_running_loop(), lambda: turns_of().requests)
        gc.enable()  # off since _serve began
        print(f"AssistantX is serving on http://{shown}:{port}/", flush=True)
        print(f"  API docs: http://{shown}:{port}/docs", flush=True)
        if offices.several:
            names = ", ".join(f"{o} ({offices.status(o)})" for o in offices.slots)
            print(f"  offices: {names}; replica {offices.replica}", flush=True)
            if offices.generated_token:
                print(f"  operator token: {offices.generated_token}", flush=True)
            return
        running = offices.serving(None)
        if running is None:  # one office on replicas: another one holds it for now
            print(f"  replica {offices.replica}: a standby until it holds the office", flush=True)
            if offices.generated_token:
                print(f"  operator token: {offices.generated_token}", flush=True)
            return
        auth = running.auth
        if auth.generated_token:
            print(
                f"  operator token (also in {auth.token_file}): {auth.generated_token}", flush=True
            )

    try:
        lock = DataDirLock(settings.data_dir).acquire()
    except DataDirBusyError as exc:
        print(f"assistantx serve: {exc}", file=sys.stderr)
        return 1
    try:
        listener = _bind(host, port)
    except OSError as exc:
        lock.release()
        print(f"assistantx serve: cannot listen on {host}:{port}: {exc.strerror}", file=sys.stderr)
        return 1
    # A replica that lost its office's lease stops (its writes are refused anyway); the
    # supervisor that restarts it makes it a standby. With several offices only the lost
    # office stops; the replica takes its share again.
    app = create_app(
        settings,
        on_ready=announce,
        data_lock=lock,
        on_lease_lost=lambda: signal.raise_signal(signal.SIGTERM),
    )
    service_server(app, host, port).run(sockets=[listener])
    return 0


def _bind(host: str, port: int) -> socket.socket:
    """The listening socket, bound before the app starts (as uvicorn would bind it)."""
    family = socket.AF_INET6 if ":" in host else socket.AF_INET
    # IPPROTO_TCP named, not 0: asyncio sets TCP_NODELAY only on connections from a socket
    # that says TCP, and without it a kept-alive response written as headers then body waited
    # for the client's delayed ACK (40 ms): every GET over a reused connection took ~45 ms.
    listener = socket.socket(family, socket.SOCK_STREAM, socket.IPPROTO_TCP)
    try:
        listener.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        listener.bind((host, port))
        listener.listen(2048)
    except OSError:
        listener.close()
        raise
    listener.set_inheritable(True)
    return listener


def _robot_files_problem(settings: Settings) -> str | None:
    """Check the office, map and anchors before serving, so a bad anchor is one line naming
    the file, the location id and the problem, not a start-up traceback (the robot built
    here is cached per file version, so the service's own costs nothing more)."""
    if settings.robot != "navigator":
        return None
    from assistantx.adapters.robot.navigator import DEFAULT_MAP, NavigatorRobot
    from assistantx.core.clock import SimClock
    from assistantx.core.errors import AssistantXError
    from assistantx.core.office import load_office

    try:
        NavigatorRobot.from_files(
            load_office(settings.office),
            SimClock(),
            map_yaml=settings.map or DEFAULT_MAP,
            anchors_yaml=settings.map_anchors,
            localize=False,
        )
    except AssistantXError as exc:
        return str(exc)
    return None
