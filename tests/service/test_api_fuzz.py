"""Schema-driven fuzzing of the service (issue 24, "fuzzing as a habit"): schemathesis reads
the service's own OpenAPI document and sends every route inputs generated from it, valid and
invalid, over real HTTP with the operator's token. No answer may be a 5xx.

The budget is bounded (``EXAMPLES`` per route, derandomized, so a failure repeats) to keep
``make test`` quick; raise ``FUZZ_EXAMPLES`` to fuzz harder locally. The event
streams are left out: a valid request to one never ends (they have their own tests).
"""

from __future__ import annotations

import json
import os
import threading
from collections.abc import Iterator
from typing import TYPE_CHECKING

import pytest
import requests
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from assistantx.core.settings import Settings
from assistantx.service.app import create_app
from assistantx.service.server import service_server
from helpers.eventually import eventually_sync
from helpers.servers import free_port
from service.server import LEE, OPERATOR

if TYPE_CHECKING:
    import schemathesis

EXAMPLES = int(os.environ.get("FUZZ_EXAMPLES", "5"))
AUTH = {"Authorization": f"Bearer {OPERATOR}"}


@pytest.fixture(scope="module")
def base_url(tmp_path_factory: pytest.TempPathFactory) -> Iterator[str]:
    """The service in a thread of its own (schemathesis calls it synchronously)."""
    data_dir = tmp_path_factory.mktemp("fuzz") / "data"
    settings_ = Settings(  # type: ignore[arg-type]
        data_dir=data_dir,
        operator_token=OPERATOR,
        tokens=json.dumps({LEE: "lee"}),
        people="human",
        speedup=200,
        max_body_bytes=4096,
    )
    port = free_port()
    server = service_server(create_app(settings_), "127.0.0.1", port, log_level="critical")
    thread = threading.Thread(target=server.run, name="fuzzed-service", daemon=True)
    thread.start()
    eventually_sync(lambda: server.started, what="the service to listen", timeout_s=60)
    try:
        yield f"http://127.0.0.1:{port}"
    finally:
        server.should_exit = True
        thread.join(30)


def _operations(base_url: str) -> list[schemathesis.APIOperation]:
    # Imported here: the worker that does not run this test need not load schemathesis (its
    # pytest plugin is off too, `-p no:schemathesis` in pyproject.toml: nothing uses it).
    import schemathesis

    schema = schemathesis.openapi.from_url(f"{base_url}/openapi.json")
    found = [result.ok() for result in schema.get_all_operations()]
    return [op for op in found if not op.path.endswith("/events")]


def test_no_route_answers_a_server_error(base_url: str) -> None:
    operations = _operations(base_url)
    assert len(operations) >= 20  # the whole API, not an empty schema
    failures: list[str] = []
    session = requests.Session()

    @settings(
        max_examples=EXAMPLES * len(operations),
        deadline=None,
        derandomize=True,
        database=None,
        suppress_health_check=list(HealthCheck),
    )
    @given(data=st.data())
    def fuzz(data: st.DataObject) -> None:
        operation = data.draw(st.sampled_from(operations), label="route")
        case = data.draw(operation.as_strategy(), label="case")
        response = case.call(base_url=base_url, session=session, headers=AUTH, timeout=30)
        if response.status_code >= 500:
            failures.append(
                f"{case.method} {case.formatted_path} -> {response.status_code}: "
                f"{response.text[:200]}\n  {case.as_curl_command()}"
            )

    fuzz()
    assert failures == [], "\n".join(failures)
