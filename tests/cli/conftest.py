from fakes.fixtures import scripted_llm  # noqa: F401
