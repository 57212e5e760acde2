"""AssistantX: an LLM-powered proactive office assistant (PPDR agents over a Memory Unit)."""

__version__ = "0.1.0"
