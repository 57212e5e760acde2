"""The service: REST and live events over FastAPI, the dashboard, auth, durability, telemetry,
and the runtime that wires the assistant to its adapters."""
