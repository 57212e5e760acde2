"""The interfaces of the outside world the runtime acts on: messenger, robot base and lock, with
their value types. Adapters implement them; agents and runtime only see these.
"""
