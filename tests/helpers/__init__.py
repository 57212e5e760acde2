"""Helpers shared by the tests: waiting for a condition, and the simulated office's wiring."""
