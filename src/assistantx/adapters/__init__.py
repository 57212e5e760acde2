"""Adapters to the outside world: messenger, robot base and smart lock.

Each sub-package holds the wire client of one kind of device or service (it knows nothing of
agents) and the adapter that maps it to a port in ``assistantx.core.ports``; the simulator in
``assistantx.sim`` implements the same ports. Every adapter (and every wire client with a
background task) is a ``core.lifecycle.Component``: idempotent start/stop, ``async with``,
and its tasks cancelled and awaited on stop.
"""
