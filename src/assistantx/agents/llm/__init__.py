"""The LLM agents: perception, planning, decision and reflection as prompts to a chat model."""
