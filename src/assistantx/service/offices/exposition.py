"""The deployment's series on ``/metrics``: which replica runs which office, and its state.

``assistantx_office_replica{office, replica}`` is 1 for the replica running each office (as
this replica last read the shared leases, or itself); ``assistantx_office_ready{office}`` is 1
where the office's assistant runs on the replica answering; ``assistantx_replica_offices
{replica}`` counts the offices each live replica runs, so a scrape of any one replica shows
the spread; ``assistantx_replica_up{replica}`` and
``assistantx_replica_heartbeat_age_seconds{replica}`` say each replica's health as the shared
leases show it. With several offices, and with one office on replicas (every replica, a
standby too, says who holds it); one office on its own keeps today's series alone.
"""

from __future__ import annotations

from collections.abc import Iterator

from prometheus_client import CollectorRegistry, generate_latest
from prometheus_client.metrics_core import GaugeMetricFamily, Metric
from prometheus_client.registry import Collector

from assistantx.service.offices.directory import READY, Offices


class _OfficeCollector(Collector):
    def __init__(self, offices: Offices) -> None:
        self._offices = offices

    def collect(self) -> Iterator[Metric]:
        offices = self._offices
        holder = GaugeMetricFamily(
            "assistantx_office_replica",
            "1 for the replica that runs each office",
            labels=["office", "replica"],
        )
        ready = GaugeMetricFamily(
            "assistantx_office_ready",
            "1 where the office's assistant runs on this replica",
            labels=["office"],
        )
        for office in offices.slots:
            replica = offices.holder(office)
            if replica is not None:
                holder.add_metric([office, replica], 1.0)
            ready.add_metric([office], 1.0 if offices.status(office) == READY else 0.0)
        counts = GaugeMetricFamily(
            "assistantx_replica_offices",
            "offices each live replica runs",
            labels=["replica"],
        )
        up = GaugeMetricFamily(
            "assistantx_replica_up",
            "1 for a replica whose heartbeat is live; 0 for one that still holds an office's"
            " lease without it",
            labels=["replica"],
        )
        age = GaugeMetricFamily(
            "assistantx_replica_heartbeat_age_seconds",
            "seconds since each live replica last heartbeat, as this replica last read the"
            " leases (a stalled replica's grows towards the lease's time)",
            labels=["replica"],
        )
        for view in offices.replicas():
            counts.add_metric([view.id], float(len(view.offices)))
            up.add_metric([view.id], 1.0 if view.up else 0.0)
            if view.heartbeat_age_s is not None:
                age.add_metric([view.id], view.heartbeat_age_s)
        yield from (holder, ready, counts, up, age)


def render_offices(offices: Offices) -> bytes:
    registry = CollectorRegistry(auto_describe=False)
    registry.register(_OfficeCollector(offices))
    return generate_latest(registry)
