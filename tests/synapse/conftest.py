"""Session fixtures: one Synapse for the whole run, and one application-service gateway; and
the office of the matrix-nio tests (`office`: Lee, Zhang, Mao, Hu and a stranger at nio clients).
Per test, the set-up most tests share: `lee` (an account and Lee's own client), `lee_config`
(the assistant's config with Lee in it), `event_store` and `pushed` (the assistant's messenger
in push mode over that store, delivering to `inbox`), each closed after the test.

The gateway is a real uvicorn server on the port written into the appservice registration. It
lives for the whole session (so Synapse never sees the assistant "down" between tests and
never backs off); each test mounts its own router on it. With nothing mounted it acknowledges
and discards, because leftover events of an earlier test concern nobody.
"""

from __future__ import annotations

import asyncio
import contextlib
import gc
import secrets
import uuid
from collections.abc import AsyncIterator, Callable, Iterator
from pathlib import Path

import pytest
import pytest_asyncio
import yaml
from pydantic import SecretStr

from assistantx.adapters.messenger.matrix import (
    MatrixClient,
    MatrixConfig,
    MatrixMessenger,
    SqliteEventStore,
)
from assistantx.cli import build_parser
from assistantx.core.ports.messenger import InboundMessage
from synapse.gateway import AppserviceGateway
from synapse.helpers import Colleague, bridge, derive
from synapse.homeserver import (
    Account,
    SynapseHomeserver,
    SynapseUnavailableError,
    free_port,
    install_synapse,
)
from synapse.nio_office import PEOPLE, MatrixService, Office, Policy, is_survey
from synapse.nio_people import NioPerson


@pytest.fixture(scope="session")
def appservice_config(tmp_path_factory: pytest.TempPathFactory) -> MatrixConfig:
    """The assistant's application service; its URL points at the gateway's port."""
    return MatrixConfig(
        homeserver_url="http://127.0.0.1:1",  # replaced once Synapse has a port
        server_name="office.test",
        as_token=SecretStr(secrets.token_hex(16)),
        hs_token=SecretStr(secrets.token_hex(16)),
        appservice_id="assistantx-test",
        appservice_url=f"http://127.0.0.1:{free_port()}",
        sender_localpart="assistant",
        mode="push",
    )


@pytest.fixture(scope="session")
def homeserver(
    tmp_path_factory: pytest.TempPathFactory, appservice_config: MatrixConfig
) -> Iterator[SynapseHomeserver]:
    try:
        python = install_synapse()
    except SynapseUnavailableError as exc:
        pytest.fail(f"cannot install Synapse: {exc}", pytrace=False)
    workdir: Path = tmp_path_factory.mktemp("synapse")
    # Written the way the README tells a user to: `assistantx matrix registration`.
    config_file = workdir / "matrix.yaml"
    raw = appservice_config.model_dump(mode="json") | {
        "as_token": appservice_config.as_token.get_secret_value(),
        "hs_token": appservice_config.hs_token.get_secret_value(),
    }
    config_file.write_text(yaml.safe_dump(raw), encoding="utf-8")
    registration = workdir / "appservice.yaml"
    command = ["matrix", "registration", "--config", str(config_file), "-o", str(registration)]
    args = build_parser().parse_args(command)  # main() minus its logging set-up
    assert args.func(args) == 0
    server = SynapseHomeserver(workdir, [registration])
    try:
        server.start(python)
    except SynapseUnavailableError as exc:
        pytest.fail(f"cannot start Synapse: {exc}", pytrace=False)
    yield server
    server.stop()


@pytest.fixture(scope="session")
def base_config(appservice_config: MatrixConfig, homeserver: SynapseHomeserver) -> MatrixConfig:
    return appservice_config.model_copy(update={"homeserver_url": homeserver.url})


@pytest_asyncio.fixture(scope="session", loop_scope="session")
async def gateway(base_config: MatrixConfig) -> AsyncIterator[AppserviceGateway]:
    assert base_config.appservice_url is not None
    port = int(base_config.appservice_url.rsplit(":", 1)[1])
    async with AppserviceGateway.serve(port) as running:
        yield running


@pytest_asyncio.fixture(loop_scope="session")
async def gateway_mounts(
    gateway: AppserviceGateway, base_config: MatrixConfig
) -> AsyncIterator[AppserviceGateway]:
    """The gateway, emptied again after the test, with Synapse's appservice back up.

    A test whose service answered one of Synapse's transactions with an error as it stopped
    leaves the appservice marked down: Synapse then holds every later event and retries after
    2, 4, 8 ... seconds, so the next test's first pushed message came after its 20 s wait
    (seen once, under load, after test_matrix_courtesy). A ping that the emptied gateway
    answers makes Synapse recover at once; what it held goes to the gateway, which discards
    it, not to the next test's messenger.
    """
    yield gateway
    gateway.unmount()
    async with MatrixClient(
        base_config.homeserver_url, base_config.as_token.get_secret_value()
    ) as client:
        await client.request(
            "POST",
            f"/_matrix/client/v1/appservice/{base_config.appservice_id}/ping",
            json={"transaction_id": f"recover-{uuid.uuid4().hex[:8]}"},
        )


@pytest.fixture
def new_account(homeserver: SynapseHomeserver) -> object:
    def register(prefix: str) -> Account:
        return homeserver.register(f"{prefix}-{uuid.uuid4().hex[:8]}")

    return register


@pytest.fixture
def inbox() -> asyncio.Queue[InboundMessage]:
    return asyncio.Queue()


@pytest_asyncio.fixture(loop_scope="session")
async def office(
    base_config: MatrixConfig,
    gateway_mounts: AppserviceGateway,
    new_account: Callable[[str], Account],
    tmp_path: Path,
) -> AsyncIterator[Office]:
    accounts = {name: new_account(name) for name in (*PEOPLE, "stranger")}
    people = {n: NioPerson(n, a, base_config.homeserver_url) for n, a in accounts.items()}
    config = derive(base_config, people={n: accounts[n].user_id for n in PEOPLE})
    services: list[MatrixService] = []

    def service_for(policy: Policy) -> MatrixService:
        service = MatrixService(config, gateway_mounts, tmp_path / "data", policy)
        services.append(service)
        return service

    async with contextlib.AsyncExitStack() as stack:
        for person in people.values():
            person.aside = is_survey
            await person.start()
            stack.push_async_callback(person.stop)
        stranger = people.pop("stranger")
        yield Office(config, people, stranger, service_for)
        for service in services:
            await service.stop()


@pytest_asyncio.fixture(loop_scope="session")
async def lee(
    homeserver: SynapseHomeserver, new_account: Callable[[str], Account]
) -> AsyncIterator[Colleague]:
    account = new_account("lee")
    async with MatrixClient(homeserver.url, account.access_token) as client:
        yield Colleague(account, client)


@pytest.fixture
def lee_config(base_config: MatrixConfig, lee: Colleague) -> MatrixConfig:
    """The assistant's config with Lee as the one person of the office."""
    return derive(base_config, people={"lee": lee.account.user_id})


@pytest_asyncio.fixture(loop_scope="session")
async def event_store(tmp_path: Path) -> AsyncIterator[SqliteEventStore]:
    """The messenger's inbound event store, closed after the test."""
    store = SqliteEventStore(tmp_path / "events.db")
    yield store
    await store.close()


@pytest.fixture
def pushed(
    lee_config: MatrixConfig,
    event_store: SqliteEventStore,
    inbox: asyncio.Queue[InboundMessage],
    gateway_mounts: AppserviceGateway,
) -> MatrixMessenger:
    """The assistant's messenger (not started) in push mode, delivering to ``inbox``."""
    return bridge(lee_config, event_store, inbox, gateway_mounts)


@pytest.fixture(autouse=True)
def _collect_garbage_before_the_next_test() -> Iterator[None]:
    """A socket a test leaves unclosed is reported in the test that leaked it, not in
    whichever later test the garbage collector happens to run in (once a source scan in
    another folder: the warning even broke its ``ast.parse``)."""
    yield
    gc.collect()
