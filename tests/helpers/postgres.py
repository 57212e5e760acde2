"""The tests' own PostgreSQL: one cluster per test session, one fresh database per test.

``initdb`` makes a cluster in a temporary folder; its ``postgres`` runs as a child of the test
process (so the leftover-process guard of ``conftest.py`` sees it) on a free loopback port,
with durability off (a test database is thrown away). Debian's binaries live under
``/usr/lib/postgresql/VERSION/bin``; ``.ci/install-postgres`` (``make test``) installs them.
PostgreSQL refuses to run as root: as root, the cluster belongs to and runs as ``nobody``.
"""

from __future__ import annotations

import ctypes
import itertools
import os
import pwd
import shutil
import signal
import subprocess
import tempfile
from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path

import pytest

from helpers.eventually import eventually_sync

UNPRIVILEGED = "nobody"
START_TIMEOUT_S = 60.0
STOP_TIMEOUT_S = 30.0
SETTINGS = {  # a throw-away cluster: no fsync, small, loopback only
    "fsync": "off",
    "synchronous_commit": "off",
    "full_page_writes": "off",
    "shared_buffers": "32MB",
    "max_connections": "100",
    "listen_addresses": "127.0.0.1",
}


def bin_dir() -> Path | None:
    """Where ``initdb`` and ``postgres`` are: PATH, else the newest Debian version."""
    found = shutil.which("initdb")
    if found:
        return Path(os.path.realpath(found)).parent
    versions = sorted(
        Path("/usr/lib/postgresql").glob("*/bin/initdb"),
        key=lambda p: int(p.parent.parent.name) if p.parent.parent.name.isdigit() else 0,
    )
    return versions[-1].parent if versions else None


@dataclass
class Cluster:
    process: subprocess.Popen[bytes]
    port: int
    folder: Path
    _names: Iterator[int] = field(default_factory=lambda: itertools.count(1))

    def url(self, dbname: str = "postgres") -> str:
        return f"postgresql://postgres@127.0.0.1:{self.port}/{dbname}"

    def new_database(self) -> str:
        """A fresh, empty database; its URL."""
        import psycopg  # only where a test has a cluster: see start_cluster

        name = f"test_{next(self._names)}"
        with psycopg.connect(self.url(), autocommit=True) as conn:
            conn.execute(f"CREATE DATABASE {name}")
        return self.url(name)

    def stop(self) -> None:
        """Fast shutdown (SIGINT), then wait for the process; a kill if it does not end."""
        if self.process.poll() is None:
            self.process.send_signal(signal.SIGINT)
            try:
                self.process.wait(STOP_TIMEOUT_S)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait()
        shutil.rmtree(self.folder, ignore_errors=True)


PR_SET_PDEATHSIG = 1


def _stop_with_parent() -> None:
    """In the child, before exec (after the switch of user): Linux sends the server SIGINT (a
    fast shutdown) when the test process dies, also by kill -9, so no cluster outlives it."""
    ctypes.CDLL(None, use_errno=True).prctl(PR_SET_PDEATHSIG, signal.SIGINT)


def start_cluster() -> Cluster:
    binaries = bin_dir()
    if binaries is None:
        pytest.fail(
            "PostgreSQL is not installed (no initdb): run `make test` or .ci/install-postgres",
            pytrace=False,
        )
    folder = Path(tempfile.mkdtemp(prefix="assistantx-pg-"))
    data = folder / "data"
    as_user: dict[str, object] = {}
    if os.getuid() == 0:
        user = pwd.getpwnam(UNPRIVILEGED)
        os.chown(folder, user.pw_uid, user.pw_gid)
        as_user = {"user": user.pw_uid, "group": user.pw_gid, "extra_groups": []}
    subprocess.run(
        [binaries / "initdb", "-D", data, "-U", "postgres", "-A", "trust", "--no-sync",
         "-E", "UTF8", "--locale=C"],
        check=True, capture_output=True, cwd=folder, **as_user,  # type: ignore[call-overload]
    )  # fmt: skip
    from helpers.servers import free_port  # FastAPI: not at import (tests/conftest.py's)

    port = free_port()
    options = [f"-c{key}={value}" for key, value in SETTINGS.items()]
    log = (folder / "postgres.log").open("wb")
    process = subprocess.Popen(  # type: ignore[call-overload]
        [binaries / "postgres", "-D", data, "-p", str(port), "-k", folder, *options],
        stdout=log, stderr=subprocess.STDOUT, cwd=folder, preexec_fn=_stop_with_parent,
        **as_user,
    )  # fmt: skip
    log.close()
    cluster = Cluster(process, port, folder)
    # psycopg is imported here, not with this module: every conftest imports it, and most runs
    # (`make test-fast`) start no cluster (0.15-0.3 CPU-s per process: each xdist worker's)
    import psycopg

    def ready() -> bool:
        if process.poll() is not None:
            raise RuntimeError(f"postgres ended: {(folder / 'postgres.log').read_text()[-2000:]}")
        with psycopg.connect(cluster.url(), connect_timeout=2):
            return True

    try:
        eventually_sync(
            ready, what="the tests' PostgreSQL", timeout_s=START_TIMEOUT_S,
            ignore=(psycopg.OperationalError,),
        )  # fmt: skip
    except BaseException:
        cluster.stop()
        raise
    return cluster


@pytest.fixture(scope="session")
def postgres_cluster() -> Iterator[Cluster]:
    cluster = start_cluster()
    try:
        yield cluster
    finally:
        cluster.stop()


@pytest.fixture
def postgres_url(postgres_cluster: Cluster) -> str:
    """A fresh database of the session's cluster, for one test."""
    return postgres_cluster.new_database()


BACKENDS = ["sqlite", pytest.param("postgres", marks=pytest.mark.postgres)]


@pytest.fixture(params=BACKENDS)
def backend(request: pytest.FixtureRequest) -> str:
    """Runs the test once per store backend: the SQLite file, then the tests' PostgreSQL."""
    name: str = request.param
    return name


@pytest.fixture
def database_url(backend: str, request: pytest.FixtureRequest) -> str | None:
    """None for SQLite; a fresh PostgreSQL database's URL otherwise."""
    if backend == "sqlite":
        return None
    url: str = request.getfixturevalue("postgres_url")
    return url
