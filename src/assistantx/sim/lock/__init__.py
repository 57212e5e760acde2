"""The simulated locker: its logic (no I/O), the in-process lock and the TCP emulator."""
