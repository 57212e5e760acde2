"""The one backoff rule: exponential, capped, full jitter, from the caller's own Random."""

from __future__ import annotations

import random

import pytest

from assistantx.core.backoff import Backoff


def test_delays_are_full_jitter_within_the_exponential_cap() -> None:
    backoff = Backoff(initial_s=0.5, max_s=8.0)
    rng = random.Random(11)
    for attempt, ceiling in enumerate([0.5, 1.0, 2.0, 4.0, 8.0, 8.0, 8.0]):
        assert backoff.ceiling_s(attempt) == ceiling
        delays = [backoff.delay_s(attempt, rng) for _ in range(200)]
        assert all(0.0 <= d <= ceiling for d in delays)
        # Full jitter, not "equal jitter" (which never waits less than half the ceiling):
        # the draws cover the whole range, down near zero and up near the cap.
        assert min(delays) < 0.05 * ceiling
        assert max(delays) > 0.95 * ceiling


def test_delays_are_reproducible_with_a_seeded_random() -> None:
    backoff = Backoff(initial_s=0.1, max_s=10.0)
    first = [backoff.delay_s(n, random.Random(5)) for n in range(6)]
    again = [backoff.delay_s(n, random.Random(5)) for n in range(6)]
    other = [backoff.delay_s(n, random.Random(6)) for n in range(6)]
    assert first == again and first != other


def test_the_global_random_does_not_shift_the_delays() -> None:
    backoff = Backoff()
    rng = random.Random(3)
    expected = [backoff.delay_s(n, rng) for n in range(4)]
    rng = random.Random(3)
    got = []
    for n in range(4):
        random.random()  # someone else draws from the module's generator meanwhile
        got.append(backoff.delay_s(n, rng))
    assert got == expected


def test_a_floor_keeps_the_delay_at_or_above_it() -> None:
    backoff = Backoff(initial_s=0.5, max_s=1.0, min_s=0.5)
    rng = random.Random(1)
    assert backoff.delay_s(0, rng) == 0.5
    assert all(0.5 <= backoff.delay_s(n, rng) <= 1.0 for n in range(1, 50))


def test_a_huge_attempt_number_stays_at_the_cap() -> None:
    assert Backoff(initial_s=1.0, max_s=30.0).ceiling_s(10_000) == 30.0


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"initial_s": -1.0}, ">= 0"),
        ({"factor": 0.5}, "factor"),
        ({"min_s": 5.0, "max_s": 1.0}, "floor"),
    ],
)
def test_a_nonsense_backoff_is_refused(kwargs: dict[str, float], message: str) -> None:
    with pytest.raises(ValueError, match=message):
        Backoff(**kwargs)
