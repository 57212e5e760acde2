"""The reasoners: the PPDR reasoner interface and every implementation (symbolic, LLM, hybrid,
baselines, ablations, the optimal oracle), and one registry that builds them by name.
"""
