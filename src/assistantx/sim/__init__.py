"""The simulated world: an office of people, a robot base and a lock that behave like the real
ones, and the wiring that runs one instruction in it (``run``)."""
