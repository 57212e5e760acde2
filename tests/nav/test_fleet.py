"""The fleet dispatcher (first cut): soonest-finish assignment, reservations so robots yield
instead of meeting in an aisle, a lease (fencing token) per robot."""

from __future__ import annotations

from assistantx.nav.fleet import Dispatcher, Trip, serve
from assistantx.nav.planner import GridPlanner


def test_a_trip_goes_to_the_robot_that_finishes_it_soonest(office_planner: GridPlanner) -> None:
    fleet = Dispatcher(office_planner, {"west": (5.0, 6.0), "east": (33.0, 6.0)})
    east = fleet.assign(Trip("a", 0.0, ((29.0, 6.0), (33.0, 13.0))))
    assert east.robot == "east"
    west = fleet.assign(Trip("b", 0.0, ((9.0, 6.0), (5.0, 13.0))))
    assert west.robot == "west"
    # The next trip goes to whichever would finish it first, busy or not.
    trip = Trip("c", 0.0, ((25.0, 6.0), (29.0, 13.0)))
    bids = {
        r.name: fleet._timed(r.position, trip, max(r.free_at_s, trip.release_s))[2]
        for r in fleet.robots.values()
    }
    later = fleet.assign(trip)
    assert later.robot == min(bids, key=bids.__getitem__)
    assert {a.lease for a in (east, west)} == {1}
    assert fleet.robots[later.robot].lease == 2  # the lease is per robot


def test_robots_meeting_in_an_aisle_yield_and_never_share_a_block(
    office_planner: GridPlanner,
) -> None:
    """Two robots sent at once along the same aisle from opposite ends: the second waits."""
    fleet = Dispatcher(office_planner, {"west": (3.0, 8.0), "east": (34.0, 8.0)})
    done = serve(
        fleet,
        [
            Trip("w", 0.0, ((3.0, 8.0), (34.0, 8.0)), dwell_s=0.0),
            Trip("e", 0.0, ((34.0, 8.0), (3.0, 8.0)), dwell_s=0.0),
        ],
    )
    robots = {a.trip: a.robot for a in done}
    assert robots == {"w": "west", "e": "east"}
    assert done[0].yielded_s == 0.0 and done[1].yielded_s > 0.0
    margin = fleet.reservations.margin_s
    for block in fleet.reservations._windows.values():
        for a0, a1, who in block:
            for b0, b1, other in block:
                if who != other:  # a pass keeps at least the margin from the other's
                    assert a1 - margin <= b0 or b1 <= a0 + margin
