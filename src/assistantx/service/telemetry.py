"""The service's metrics: instructions by status, step and agent latencies, tokens, errors.

Every agent call is timed in ``assistantx_agent_call_latency_seconds`` labelled with its agent
and ``backend`` (``llm`` or ``embedded``); ``assistantx_llm_call_latency_seconds`` and the
token counter hold only calls that went to a language model, so the embedded, model-free
reasoner never shows up as LLM traffic.

The series live in ``prometheus_client`` metrics on a registry of this object's own, never the
library's process-global default: two apps in one process (the tests start many) each count
only their own traffic, and registering the same names twice cannot collide.
"""

from __future__ import annotations

import time
from collections import Counter as Tally
from collections.abc import Callable, Iterable, Iterator, Sequence

from prometheus_client import CollectorRegistry, Counter, Gauge, Histogram
from prometheus_client.exposition import CONTENT_TYPE_PLAIN_0_0_4, generate_latest
from prometheus_client.metrics_core import CounterMetricFamily, GaugeMetricFamily, Metric

from assistantx.core.isolation import SkippedEvents
from assistantx.core.trace import TraceStep
from assistantx.service.loop_lag import LoopLagMonitor
from assistantx.store.journal import Journal
from assistantx.store.leases import Lease

CONTENT_TYPE = CONTENT_TYPE_PLAIN_0_0_4  # the text format every Prometheus server reads
LATENCY_BUCKETS = (0.005, 0.01, 0.025, 0.05, 0.1, 0.25, 0.5, 1.0, 2.5, 5.0, 10.0, 30.0, 60.0)
STEP_BUCKETS = (0.01, 0.05, 0.1, 0.5, 1.0, 5.0, 10.0, 30.0, 60.0, 300.0, 900.0)


class _InstructionsByStatus:
    """A gauge family read from the journal at scrape time (the journal is the truth)."""

    NAME = "assistantx_instructions"

    def __init__(self, journal: Journal) -> None:
        self._journal = journal

    def describe(self) -> Iterable[Metric]:  # lets the registry refuse a duplicate name
        return [GaugeMetricFamily(self.NAME, "instructions by status", labels=["status"])]

    def collect(self) -> Iterable[Metric]:
        family = GaugeMetricFamily(self.NAME, "instructions by status", labels=["status"])
        for status, n in self._journal.count_by_status().items():
            family.add_metric([status], float(n))
        return [family]


class _SkippedInbound:
    """A counter family read at scrape time from the inbound paths' ``SkippedEvents``."""

    NAME = "assistantx_inbound_events_skipped"
    HELP = "inbound events skipped because handling them raised, by path"

    def __init__(self, sources: Sequence[SkippedEvents]) -> None:
        self._sources = sources

    def describe(self) -> Iterable[Metric]:
        return [CounterMetricFamily(self.NAME, self.HELP, labels=["path"])]

    def collect(self) -> Iterable[Metric]:
        family = CounterMetricFamily(self.NAME, self.HELP, labels=["path"])
        totals: Tally[str] = Tally()
        for source in self._sources:
            totals.update(source.by_path)
        for path in sorted(totals):
            family.add_metric([path], float(totals[path]))
        return [family]


class _OfficeLease:
    """Which replica runs which office, read at scrape time from the lease this replica holds.

    ``assistantx_office_lease_token{office, replica}`` is the fencing token (it only grows, so a
    change tells a failover happened), ``assistantx_office_lease_expires_in_seconds`` how long
    the lease lasts without a renewal (near zero or negative: the renewals stall) and
    ``assistantx_replica_ready{replica}`` whether the assistant runs. These come from the
    holder; every replica (a standby too) adds which replica holds the office
    (``offices.exposition``). Without a database URL there is no lease and no series."""

    def __init__(
        self,
        lease: Callable[[], Lease | None],
        ready: Callable[[], bool],
        clock: Callable[[], float],
    ) -> None:
        self._lease = lease
        self._ready = ready
        self._clock = clock

    def describe(self) -> Iterable[Metric]:
        return self._families()

    def collect(self) -> Iterable[Metric]:
        token, expires, ready = self._families()
        lease = self._lease()
        if lease is not None:
            labels = [lease.office, lease.holder]
            token.add_metric(labels, float(lease.token))
            expires.add_metric(labels, lease.expires_at - self._clock())
            ready.add_metric([lease.holder], 1.0 if self._ready() else 0.0)
        return [token, expires, ready]

    @staticmethod
    def _families() -> list[GaugeMetricFamily]:
        return [
            GaugeMetricFamily(
                "assistantx_office_lease_token",
                "fencing token of the office lease this replica holds",
                labels=["office", "replica"],
            ),
            GaugeMetricFamily(
                "assistantx_office_lease_expires_in_seconds",
                "seconds until the office lease expires unless renewed",
                labels=["office", "replica"],
            ),
            GaugeMetricFamily(
                "assistantx_replica_ready",
                "1 while this replica runs the assistant",
                labels=["replica"],
            ),
        ]


class _WithoutCreated:
    """The registry's families less the ``*_created`` series prometheus_client adds to each
    counter and histogram child: they would double the series we expose and change no reading;
    the library's switch for them is process-global, so they are left out here instead."""

    def __init__(self, registry: CollectorRegistry) -> None:
        self._registry = registry

    def collect(self) -> Iterator[Metric]:
        for family in self._registry.collect():
            created = family.name + "_created"
            family.samples = [s for s in family.samples if s.name != created]
            yield family


class ServiceMetrics:
    def __init__(self, journal: Journal) -> None:
        self.registry = CollectorRegistry()
        r = self.registry
        r.register(_InstructionsByStatus(journal))
        self.steps = Histogram(
            "assistantx_step_duration_seconds",
            "duration of one PPDR step (clock seconds)",
            buckets=STEP_BUCKETS,
            registry=r,
        )
        self.agent_latency = Histogram(
            "assistantx_agent_call_latency_seconds",
            "latency of one agent call, by agent and backend (llm or embedded)",
            ["agent", "backend"],
            buckets=LATENCY_BUCKETS,
            registry=r,
        )
        self.llm_latency = Histogram(
            "assistantx_llm_call_latency_seconds",
            "latency of one agent call to a language model",
            ["agent"],
            buckets=LATENCY_BUCKETS,
            registry=r,
        )
        self.tokens = Counter("assistantx_llm_tokens_total", "tokens by kind", ["kind"], registry=r)
        self.adapter_errors = Counter(
            "assistantx_adapter_errors_total",
            "failed adapter calls by error type",
            ["error"],
            registry=r,
        )
        self.http_requests = Counter(
            "assistantx_http_requests_total",
            "HTTP requests by method, route, status",
            ["method", "route", "status"],
            registry=r,
        )
        self.http_latency = Histogram(
            "assistantx_http_request_duration_seconds",
            "HTTP request latency",
            ["route"],
            buckets=LATENCY_BUCKETS,
            registry=r,
        )
        self.skipped_sends: Callable[[], int] = lambda: 0
        Gauge(
            "assistantx_duplicate_sends_skipped",
            "sends answered from the journal instead of sent again (since start)",
            registry=r,
        ).set_function(lambda: float(self.skipped_sends()))
        self._skipped_sources: list[SkippedEvents] = []
        r.register(_SkippedInbound(self._skipped_sources))
        self._exposed = _WithoutCreated(r)

    def watch_loop(self, monitor: LoopLagMonitor) -> None:
        Gauge(
            "assistantx_event_loop_lag_max_seconds",
            "the longest the event loop was blocked in the last minute",
            registry=self.registry,
        ).set_function(monitor.max_lag_s)
        Gauge(
            "assistantx_event_loop_own_lag_max_seconds",
            "the longest the service's own code held the event loop in the last minute "
            "(the lag less the loop thread's waits for a CPU, where Linux reports them)",
            registry=self.registry,
        ).set_function(monitor.max_own_lag_s)

    def watch_streams(self, open_streams: Callable[[], int]) -> None:
        Gauge(
            "assistantx_event_streams",
            "live event streams (SSE) subscribed to the journal's events",
            registry=self.registry,
        ).set_function(lambda: float(open_streams()))

    def watch_lease(
        self,
        lease: Callable[[], Lease | None],
        ready: Callable[[], bool],
        clock: Callable[[], float] = time.time,
    ) -> None:
        """Expose the office lease ``lease()`` returns (replicas on PostgreSQL)."""
        self.registry.register(_OfficeLease(lease, ready, clock))

    def count_skipped(self, *sources: SkippedEvents) -> None:
        """Expose the inbound events ``sources`` skipped (``core.isolation``)."""
        self._skipped_sources.extend(sources)

    def step_completed(self, step: TraceStep) -> None:
        if step.ended_at is not None:
            self.steps.observe(max(0.0, step.ended_at - step.started_at))
        for call in step.calls:
            backend = "llm" if call.llm else "embedded"
            self.agent_latency.labels(agent=call.agent, backend=backend).observe(call.latency_s)
            if not call.llm:
                continue
            self.llm_latency.labels(agent=call.agent).observe(call.latency_s)
            self.tokens.labels(kind="prompt").inc(call.prompt_tokens)
            self.tokens.labels(kind="completion").inc(call.completion_tokens)

    def action_failed(self, error: str) -> None:
        self.adapter_errors.labels(error=error).inc()

    def request_served(self, method: str, route: str, status: int, seconds: float) -> None:
        self.http_requests.labels(method=method, route=route, status=str(status)).inc()
        self.http_latency.labels(route=route).observe(seconds)

    def render(self) -> bytes:
        """The text exposition (format 0.0.4), written by prometheus_client."""
        return generate_latest(self._exposed)
