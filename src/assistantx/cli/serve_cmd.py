"""``assistantx serve [--host H] [--port P]``: the REST API, live events and the dashboard."""

from __future__ import annotations

import argparse

from assistantx.settings import Settings


def register(sub: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    p = sub.add_parser("serve", help="run the assistant as a service (REST API + dashboard)")
    p.add_argument("--host", default=None, help="bind address (default: ASSISTANTX_HOST)")
    p.add_argument("--port", type=int, default=None, help="port (default: ASSISTANTX_PORT)")
    p.set_defaults(func=_serve)


def _serve(args: argparse.Namespace) -> int:
    from assistantx.service.app import create_app
    from assistantx.service.runtime import ServiceRuntime
    from assistantx.service.server import service_server

    settings = Settings()
    problem = _robot_files_problem(settings)
    if problem is not None:
        print(f"error: {problem}")
        return 2
    host = args.host or settings.host
    port = args.port if args.port is not None else settings.port
    shown = "127.0.0.1" if host in ("0.0.0.0", "::") else host

    def announce(runtime: ServiceRuntime) -> None:
        print(f"AssistantX is serving on http://{shown}:{port}/", flush=True)
        print(f"  API docs: http://{shown}:{port}/docs", flush=True)
        if runtime.auth.generated_token:
            print(
                f"  operator token (also in {runtime.auth.token_file}): "
                f"{runtime.auth.generated_token}",
                flush=True,
            )

    app = create_app(settings, on_ready=announce)
    service_server(app, host, port).run()
    return 0


def _robot_files_problem(settings: Settings) -> str | None:
    """Check the office, map and anchors before serving, so a bad anchor is one line naming
    the file, the location id and the problem, not a start-up traceback (the robot built
    here is cached per file version, so the service's own costs nothing more)."""
    if settings.robot != "navigator":
        return None
    from assistantx.adapters.robot.navigator import DEFAULT_MAP, NavigatorRobot
    from assistantx.clock import SimClock
    from assistantx.errors import AssistantXError
    from assistantx.office import load_office

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
