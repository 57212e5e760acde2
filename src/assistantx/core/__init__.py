"""The office, actions and their value types, the task schema, updates, trace, errors, clock and
settings, and the ports (interfaces) the adapters implement. Imports nothing above it.
"""
