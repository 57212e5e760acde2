"""The running assistant: instructions, the PPDR loop, the executors that act through the ports,
replies and leases.
"""
