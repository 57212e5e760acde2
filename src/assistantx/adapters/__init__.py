"""Adapters to the outside world: messenger, robot base and smart lock.

Each sub-package holds an interface (``base.py``) and its implementations; the simulator in
``assistantx.sim`` implements the same interfaces.
"""
