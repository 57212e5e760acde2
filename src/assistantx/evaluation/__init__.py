"""The evaluator: methods run over a task file in the simulated office, scored and reported."""

from assistantx.agents.ablations import ABLATIONS, NoPerception, NoPlanning, NoReflection
from assistantx.agents.baseline_names import BASELINES
from assistantx.agents.baselines import BaselineFactory, BaselineReasoner
from assistantx.evaluation.episode import Episode, Handover
from assistantx.evaluation.harness import EvalConfig, evaluate, load_episodes, run_episode
from assistantx.evaluation.methods import METHODS, MethodBuilder, MethodSpec
from assistantx.evaluation.metrics import Scores, judge_actions, score, success
from assistantx.evaluation.report import summarize, write_report

__all__ = [
    "ABLATIONS",
    "BASELINES",
    "METHODS",
    "BaselineFactory",
    "BaselineReasoner",
    "Episode",
    "EvalConfig",
    "Handover",
    "MethodBuilder",
    "MethodSpec",
    "NoPerception",
    "NoPlanning",
    "NoReflection",
    "Scores",
    "evaluate",
    "judge_actions",
    "load_episodes",
    "run_episode",
    "score",
    "success",
    "summarize",
    "write_report",
]
