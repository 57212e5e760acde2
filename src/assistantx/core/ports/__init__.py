"""The interfaces of the outside world: messenger, robot base and lock (the runtime acts on
them) and the chat model (the agents reason with it), with their value types. Adapters
implement them, each as a ``core.lifecycle.Component``; agents and runtime only see these.
"""
