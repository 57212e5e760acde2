"""/metrics parses as Prometheus text: each family has its declared type and, after a real
instruction, the values the run's trace and the requests made imply; two apps in one process
each count only their own."""

from __future__ import annotations

import asyncio
from collections import Counter
from contextlib import closing
from pathlib import Path
from typing import Any

import pytest
from prometheus_client.parser import text_string_to_metric_families
from prometheus_client.samples import Sample

from assistantx.core.trace import AgentCall, TraceStep
from assistantx.service.telemetry import ServiceMetrics
from assistantx.store.journal import Journal
from service.test_dashboard import serve

# The name the parser gives each family (a counter's without its ``_total``) and its type.
TYPES = {
    "assistantx_instructions": "gauge",
    "assistantx_step_duration_seconds": "histogram",
    "assistantx_agent_call_latency_seconds": "histogram",
    "assistantx_llm_call_latency_seconds": "histogram",
    "assistantx_llm_tokens": "counter",
    "assistantx_adapter_errors": "counter",
    "assistantx_http_requests": "counter",
    "assistantx_http_request_duration_seconds": "histogram",
    "assistantx_duplicate_sends_skipped": "gauge",
    "assistantx_event_loop_lag_max_seconds": "gauge",
    "assistantx_event_loop_own_lag_max_seconds": "gauge",
    "assistantx_event_streams": "gauge",
    "assistantx_inbound_events_skipped": "counter",
    "assistantx_robot_busy": "gauge",
    "assistantx_robot_driving": "gauge",
    "assistantx_robot_odometer_meters": "gauge",
    "assistantx_robot_instructions_served": "gauge",
}

Key = tuple[tuple[str, str], ...]


def _families(text: str) -> dict[str, list[Sample]]:
    """Each family's samples, after checking every family carries its declared type."""
    parsed = list(text_string_to_metric_families(text))
    assert {f.name: f.type for f in parsed} == TYPES
    return {f.name: f.samples for f in parsed}


def _values(samples: list[Sample], name: str) -> dict[Key, float]:
    return {tuple(sorted(s.labels.items())): s.value for s in samples if s.name == name}


def _check_buckets(samples: list[Sample], name: str) -> None:
    """Cumulative buckets per series, the +Inf one equal to the series' count."""
    series: dict[Key, list[float]] = {}
    for s in samples:
        if s.name == f"{name}_bucket":
            key = tuple(sorted((k, v) for k, v in s.labels.items() if k != "le"))
            series.setdefault(key, []).append(s.value)
    counts = _values(samples, f"{name}_count")
    assert set(series) == set(counts), name
    for key, cumulative in series.items():
        assert cumulative == sorted(cumulative), (name, key)
        assert cumulative[-1] == counts[key], (name, key)


async def test_each_family_has_its_type_and_the_values_of_a_real_run(tmp_path: Path) -> None:
    async with serve(tmp_path, people="simulated", reasoner_builder=None) as client:
        created = await client.post(
            "/v1/instructions", json={"requester": "lee", "text": "Bring me a stapler"}
        )
        assert created.status_code == 202, created.text
        polls = 0
        for _ in range(600):
            reply = await client.get(created.headers["location"])
            polls += 1
            assert reply.status_code == 200
            record: dict[str, Any] = reply.json()
            if record["status"] not in ("queued", "running"):
                break
            await asyncio.sleep(0.1)
        assert record["status"] not in ("queued", "running")
        text = (await client.get("/metrics")).text
    families = _families(text)
    steps = record["trace"]["steps"]
    calls = [c for step in steps for c in step["calls"]]
    assert calls and not any(c["llm"] for c in calls)  # the embedded reasoner

    assert _values(families["assistantx_instructions"], "assistantx_instructions") == {
        (("status", record["status"]),): 1.0
    }

    ended = [s["ended_at"] - s["started_at"] for s in steps if s["ended_at"] is not None]
    step_samples = families["assistantx_step_duration_seconds"]
    _check_buckets(step_samples, "assistantx_step_duration_seconds")
    assert _values(step_samples, "assistantx_step_duration_seconds_count") == {(): len(ended)}
    assert _values(step_samples, "assistantx_step_duration_seconds_sum")[()] == pytest.approx(
        sum(ended)
    )

    agent_samples = families["assistantx_agent_call_latency_seconds"]
    _check_buckets(agent_samples, "assistantx_agent_call_latency_seconds")
    per_agent = Counter(c["agent"] for c in calls)
    assert _values(agent_samples, "assistantx_agent_call_latency_seconds_count") == {
        (("agent", agent), ("backend", "embedded")): n for agent, n in per_agent.items()
    }
    sums = _values(agent_samples, "assistantx_agent_call_latency_seconds_sum")
    for agent in per_agent:
        latency = sum(c["latency_s"] for c in calls if c["agent"] == agent)
        assert sums[(("agent", agent), ("backend", "embedded"))] == pytest.approx(latency)

    assert families["assistantx_llm_call_latency_seconds"] == []
    assert families["assistantx_llm_tokens"] == []

    failures = Counter(
        r["error"] for s in steps for r in s["results"] if r["error"] and not r["refused"]
    )
    assert _values(families["assistantx_adapter_errors"], "assistantx_adapter_errors_total") == {
        (("error", error),): n for error, n in failures.items()
    }

    # The /metrics request itself is counted once it has been answered: not in this scrape.
    http = families["assistantx_http_requests"]
    assert _values(http, "assistantx_http_requests_total") == {
        (("method", "POST"), ("route", "/v1/instructions"), ("status", "202")): 1.0,
        (("method", "GET"), ("route", "/v1/instructions/{instruction_id}"), ("status", "200")): (
            polls
        ),
    }
    latency = families["assistantx_http_request_duration_seconds"]
    _check_buckets(latency, "assistantx_http_request_duration_seconds")
    assert _values(latency, "assistantx_http_request_duration_seconds_count") == {
        (("route", "/v1/instructions"),): 1.0,
        (("route", "/v1/instructions/{instruction_id}"),): polls,
    }

    inbound = families["assistantx_inbound_events_skipped"]
    assert _values(inbound, "assistantx_inbound_events_skipped_total") == {
        (("path", "dispatch"),): 0.0
    }
    skipped = families["assistantx_duplicate_sends_skipped"]
    assert _values(skipped, "assistantx_duplicate_sends_skipped") == {(): 0.0}
    lag = _values(
        families["assistantx_event_loop_lag_max_seconds"], "assistantx_event_loop_lag_max_seconds"
    )
    assert list(lag) == [()] and lag[()] >= 0.0
    own = _values(
        families["assistantx_event_loop_own_lag_max_seconds"],
        "assistantx_event_loop_own_lag_max_seconds",
    )
    assert list(own) == [()] and 0.0 <= own[()] <= lag[()]
    streams = families["assistantx_event_streams"]
    assert _values(streams, "assistantx_event_streams") == {(): 0.0}  # none is open here


def _llm_step(prompt_tokens: int, completion_tokens: int) -> TraceStep:
    call = AgentCall(
        agent="planning",
        prompt_tokens=prompt_tokens,
        completion_tokens=completion_tokens,
        latency_s=0.3,
    )
    return TraceStep(index=0, started_at=10.0, ended_at=12.0, calls=[call])


def test_two_apps_in_one_process_keep_their_own_counts(tmp_path: Path) -> None:
    def read(metrics: ServiceMetrics) -> dict[str, list[Sample]]:
        text = metrics.render().decode()
        types = {f.name: f.type for f in text_string_to_metric_families(text)}
        # The loop-lag, event-stream and robot gauges are the runtime's: a bare ServiceMetrics
        # has none.
        runtimes = ("event_loop_", "event_streams", "robot_")
        assert types == {k: v for k, v in TYPES.items() if not any(r in k for r in runtimes)}
        return {f.name: f.samples for f in text_string_to_metric_families(text)}

    with (
        closing(Journal.open(tmp_path / "first.sqlite3")) as first_journal,
        closing(Journal.open(tmp_path / "second.sqlite3")) as second_journal,
    ):
        first = ServiceMetrics(first_journal)
        second = ServiceMetrics(second_journal)  # the same names again, in the same process
        first.step_completed(_llm_step(120, 30))
        first.action_failed("lock_timeout")
        second.step_completed(_llm_step(7, 2))
        one, two = read(first), read(second)
    assert _values(one["assistantx_llm_tokens"], "assistantx_llm_tokens_total") == {
        (("kind", "prompt"),): 120.0,
        (("kind", "completion"),): 30.0,
    }
    assert _values(two["assistantx_llm_tokens"], "assistantx_llm_tokens_total") == {
        (("kind", "prompt"),): 7.0,
        (("kind", "completion"),): 2.0,
    }
    llm = "assistantx_llm_call_latency_seconds"
    assert _values(one[llm], f"{llm}_count") == {(("agent", "planning"),): 1.0}
    assert _values(one[llm], f"{llm}_sum") == {(("agent", "planning"),): pytest.approx(0.3)}
    agent = "assistantx_agent_call_latency_seconds_count"
    assert _values(two["assistantx_agent_call_latency_seconds"], agent) == {
        (("agent", "planning"), ("backend", "llm")): 1.0
    }
    errors = "assistantx_adapter_errors"
    assert _values(one[errors], f"{errors}_total") == {(("error", "lock_timeout"),): 1.0}
    assert two[errors] == []
