"""The service's metrics: instructions by status, step and agent latencies, tokens, errors.

Every agent call is timed in ``assistantx_agent_call_latency_seconds`` labelled with its agent
and ``backend`` (``llm`` or ``embedded``); ``assistantx_llm_call_latency_seconds`` and the
token counter hold only calls that went to a language model, so the embedded, model-free
reasoner never shows up as LLM traffic."""

from __future__ import annotations

from collections.abc import Callable

from assistantx.core.trace import TraceStep
from assistantx.memory.journal import Journal
from assistantx.service.loop_lag import LoopLagMonitor
from assistantx.service.prometheus import Counter, Gauge, Histogram, Labels, Registry

STEP_BUCKETS = (0.01, 0.05, 0.1, 0.5, 1.0, 5.0, 10.0, 30.0, 60.0, 300.0, 900.0)


class ServiceMetrics:
    def __init__(self, journal: Journal) -> None:
        self.registry = Registry()
        r = self.registry

        def by_status() -> dict[Labels, float]:
            return {(("status", k),): float(v) for k, v in journal.count_by_status().items()}

        r.register(Gauge("assistantx_instructions", "instructions by status", by_status))
        self.steps = r.register(
            Histogram(
                "assistantx_step_duration_seconds",
                "duration of one PPDR step (clock seconds)",
                STEP_BUCKETS,
            )
        )
        self.agent_latency = r.register(
            Histogram(
                "assistantx_agent_call_latency_seconds",
                "latency of one agent call, by agent and backend (llm or embedded)",
            )
        )
        self.llm_latency = r.register(
            Histogram(
                "assistantx_llm_call_latency_seconds",
                "latency of one agent call to a language model",
            )
        )
        self.tokens = r.register(Counter("assistantx_llm_tokens_total", "tokens by kind"))
        self.adapter_errors = r.register(
            Counter("assistantx_adapter_errors_total", "failed adapter calls by error type")
        )
        self.http_requests = r.register(
            Counter("assistantx_http_requests_total", "HTTP requests by method, route, status")
        )
        self.http_latency = r.register(
            Histogram("assistantx_http_request_duration_seconds", "HTTP request latency")
        )
        self.skipped_sends: Callable[[], int] = lambda: 0
        r.register(
            Gauge(
                "assistantx_duplicate_sends_skipped",
                "sends answered from the journal instead of sent again (since start)",
                lambda: {(): float(self.skipped_sends())},
            )
        )

    def watch_loop(self, monitor: LoopLagMonitor) -> None:
        self.registry.register(
            Gauge(
                "assistantx_event_loop_lag_max_seconds",
                "the longest the event loop was blocked in the last minute",
                lambda: {(): monitor.max_lag_s()},
            )
        )

    def step_completed(self, step: TraceStep) -> None:
        if step.ended_at is not None:
            self.steps.observe(max(0.0, step.ended_at - step.started_at))
        for call in step.calls:
            backend = "llm" if call.llm else "embedded"
            self.agent_latency.observe(call.latency_s, agent=call.agent, backend=backend)
            if not call.llm:
                continue
            self.llm_latency.observe(call.latency_s, agent=call.agent)
            self.tokens.inc(call.prompt_tokens, kind="prompt")
            self.tokens.inc(call.completion_tokens, kind="completion")

    def action_failed(self, error: str) -> None:
        self.adapter_errors.inc(error=error)

    def render(self) -> str:
        return self.registry.render()
