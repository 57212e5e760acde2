"""Fakes for tests: a scripted OpenAI-compatible LLM server and the fixtures that run it."""
