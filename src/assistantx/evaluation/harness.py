"""The evaluation harness: every (task, run) pair in a fresh simulated office, scored.

Episodes run one after another, or in ``jobs`` worker processes. Each finished episode is
appended to ``results.jsonl`` at once, so an interrupted evaluation resumes where it stopped:
pairs already in the file are skipped (``meta.json`` makes sure it is the same method).
"""

from __future__ import annotations

import asyncio
import json
import logging
import time
from collections.abc import Callable, Iterator
from concurrent.futures import FIRST_COMPLETED, Future, ProcessPoolExecutor, wait
from dataclasses import asdict, dataclass, field
from pathlib import Path

from assistantx.core.errors import AssistantXError, DatasetError
from assistantx.core.office import Office, PersonId, load_office
from assistantx.core.settings import Settings
from assistantx.evaluation.dataset.tasks import Task, load_tasks
from assistantx.evaluation.episode import Episode, Handover, SentOut
from assistantx.evaluation.methods import MethodBuilder, MethodSpec, ModelBuilder
from assistantx.evaluation.metrics import success
from assistantx.evaluation.relevance import relevant_people, relevant_places
from assistantx.runtime.loop import LoopLimits
from assistantx.sim.requester import Wish
from assistantx.sim.run import run_in_sim
from assistantx.sim.world import LOCKER

logger = logging.getLogger(__name__)

RESULTS = "results.jsonl"
META = "meta.json"


@dataclass(frozen=True)
class EvalConfig:
    tasks: Path
    out: Path
    method: str = "ppdr"
    reasoner: str = "symbolic"
    runs: int = 1
    levels: tuple[str, ...] = ()
    limit: int | None = None
    jobs: int = 1
    office: Path | None = None  # default: office.yaml beside the tasks, else the default
    max_steps: int = 30

    @property
    def spec(self) -> MethodSpec:
        return MethodSpec(self.method, self.reasoner)


@dataclass
class Progress:
    """Counts for the progress line; ``report`` is called after every episode."""

    total: int
    done: int = 0
    successes: int = 0
    skipped: int = 0
    started: float = field(default_factory=time.monotonic)

    @property
    def sr(self) -> float:
        return self.successes / self.done if self.done else 0.0


def select_tasks(config: EvalConfig, office: Office) -> list[Task]:
    tasks = load_tasks(config.tasks, office)
    if config.levels:
        unknown = set(config.levels) - {"L1", "L2", "L3"}
        if unknown:
            raise DatasetError(f"unknown level(s) {sorted(unknown)}; use L1, L2, L3")
        tasks = [t for t in tasks if t.level in config.levels]
    if config.limit is not None:
        tasks = tasks[: config.limit]
    return tasks


def office_path(config: EvalConfig) -> Path | None:
    if config.office is not None:
        return config.office
    beside = config.tasks.resolve().parent / "office.yaml"
    return beside if beside.is_file() else None


async def run_episode(
    task: Task,
    run: int,
    office: Office,
    builder: MethodBuilder,
    max_steps: int = 30,
    wall_s: float | None = 900.0,
) -> Episode:
    """One task, one run, a fresh simulated office; never raises for a method's failure."""
    people = relevant_people(office, task.requester, task.goal)
    people |= relevant_people(office, task.requester, _requested(task))
    started = time.perf_counter()
    error = None
    try:
        sim_run = await run_in_sim(
            office,
            PersonId(task.requester),  # the dataset's edge: checked when the tasks loaded
            task.instruction,
            builder.factory(task),
            unavailable=task.unavailable,
            limits=LoopLimits(max_steps=max_steps, wall_s=wall_s),
            reasoner_name=builder.spec.label,
            seed=run,
            # what they asked for, also when it cannot be done (an unachievable task's goal is
            # only to be told): a question back is answered from the request, not "nothing"
            wish=Wish.from_goal(
                office, task.requester, [*task.goal, *_requested(task)], task.spec or ()
            ),
        )
    except AssistantXError as exc:
        raise DatasetError(f"task {task.id} could not start: {exc}") from exc
    trace, sim = sim_run.trace, sim_run.sim
    if trace.outcome is None:
        error = "the instruction did not end"
    handovers = [
        Handover(item=str(e.detail["item"]), to=str(e.detail["to"]), time=e.time)
        for e in sim.world.handovers()
        if e.detail["to"] != LOCKER and any(p.id == e.detail["to"] for p in office.people)
    ]
    return Episode(
        task_id=task.id,
        run=run,
        method=builder.spec.label,
        level=task.level,
        achievable=task.achievable,
        requester=task.requester,
        unavailable=task.unavailable,
        goal=task.goal,
        optimal_actions=task.optimal_actions,
        requested_goal=_requested(task),
        relevant_people=sorted(people),
        relevant_places=sorted(relevant_places(office, people)),
        milestones=sim.check(task.goal),
        handovers=handovers,
        sent_out=[
            SentOut(item=str(e.detail["item"]), told=str(e.detail["told"]))
            for e in sim.world.sent_out()
        ],
        destinations=[p.destination for p in task.spec or () if p.destination],
        trace=trace,
        wall_s=round(time.perf_counter() - started, 4),
        sim_time_s=round(sim.clock.now(), 1),
        distance_m=round(sim.robot.odometer_m, 1),
        error=error,
    )


def _requested(task: Task) -> list[dict[str, object]]:
    extra = task.model_extra or {}
    requested = extra.get("requested_goal", [])
    return list(requested) if isinstance(requested, list) else []


def finished_pairs(out: Path) -> set[tuple[str, int]]:
    file = out / RESULTS
    if not file.is_file():
        return set()
    pairs = set()
    for line in file.read_text(encoding="utf-8").splitlines():
        if line.strip():
            try:
                data = json.loads(line)
                pairs.add((str(data["task_id"]), int(data["run"])))
            except (ValueError, KeyError):
                logger.warning("ignoring a damaged line in %s", file)  # a cut-off last line
    return pairs


def load_episodes(out: Path) -> list[Episode]:
    file = out / RESULTS
    episodes = []
    for line in file.read_text(encoding="utf-8").splitlines():
        if line.strip():
            try:
                episodes.append(Episode.model_validate_json(line))
            except ValueError:
                logger.warning("ignoring a damaged line in %s", file)
    return episodes


def _drop_partial_line(file: Path) -> None:
    """An interrupted write leaves a last line without its newline: cut it off, so the next
    episode starts on a line of its own (the cut episode is simply run again)."""
    if not file.is_file():
        return
    data = file.read_bytes()
    if data and not data.endswith(b"\n"):
        keep = data.rfind(b"\n") + 1
        logger.warning("dropping an unfinished last line of %s", file)
        with file.open("r+b") as f:
            f.truncate(keep)


def _check_meta(config: EvalConfig) -> None:
    meta = {"method": config.method, "reasoner": config.reasoner, "tasks": str(config.tasks)}
    file = config.out / META
    if file.is_file():
        old = json.loads(file.read_text(encoding="utf-8"))
        if (old.get("method"), old.get("reasoner")) != (config.method, config.reasoner):
            raise DatasetError(
                f"{config.out} holds results of {old.get('method')} ({old.get('reasoner')}); "
                "choose another --out to evaluate a different method"
            )
    config.out.mkdir(parents=True, exist_ok=True)
    file.write_text(json.dumps(meta, indent=2), encoding="utf-8")


def pending(config: EvalConfig, tasks: list[Task]) -> Iterator[tuple[Task, int]]:
    done = finished_pairs(config.out)
    for run in range(config.runs):
        for task in tasks:
            if (task.id, run) not in done:
                yield task, run


def evaluate(
    config: EvalConfig,
    settings: Settings,
    on_episode: Callable[[Episode, Progress], None] | None = None,
    *,
    build_model: ModelBuilder | None = None,
) -> list[Task]:
    """Run every pending (task, run) pair, appending each episode; returns the tasks.
    ``build_model`` gives the LLM methods their chat model (in each worker process)."""
    path = office_path(config)
    office = load_office(path)
    tasks = select_tasks(config, office)
    _check_meta(config)
    todo = list(pending(config, tasks))
    progress = Progress(total=len(tasks) * config.runs)
    progress.skipped = progress.total - len(todo)
    results = config.out / RESULTS
    _drop_partial_line(results)
    with results.open("a", encoding="utf-8") as sink:

        def record(line: str) -> None:
            episode = Episode.model_validate_json(line)
            sink.write(line + "\n")
            sink.flush()
            progress.done += 1
            progress.successes += success(episode)
            if on_episode is not None:
                on_episode(episode, progress)

        if config.jobs <= 1:
            builder = MethodBuilder(config.spec, office, settings, build_model=build_model)
            for task, run in todo:
                episode = asyncio.run(
                    run_episode(
                        task,
                        run,
                        office,
                        builder,
                        config.max_steps,
                        wall_s=settings.instruction_wall_s,
                    )
                )
                record(episode.model_dump_json())
        else:
            _run_parallel(config, path, todo, record, build_model)
    return tasks


def _run_parallel(
    config: EvalConfig,
    path: Path | None,
    todo: list[tuple[Task, int]],
    record: Callable[[str], None],
    build_model: ModelBuilder | None,
) -> None:
    # Paths (tasks, out, office) travel as text: a worker reads them back from JSON.
    job = json.dumps({k: str(v) if isinstance(v, Path) else v for k, v in asdict(config).items()})
    with ProcessPoolExecutor(max_workers=config.jobs) as pool:
        waiting: set[Future[str]] = set()
        queue = list(todo)
        while queue or waiting:
            while queue and len(waiting) < 2 * config.jobs:
                task, run = queue.pop(0)
                waiting.add(
                    pool.submit(
                        _episode_job,
                        job,
                        str(path) if path else None,
                        task.model_dump_json(),
                        run,
                        build_model,
                    )
                )
            finished, waiting = wait(waiting, return_when=FIRST_COMPLETED)
            for future in finished:
                record(future.result())


_WORKER: dict[str, MethodBuilder] = {}


def _episode_job(
    job: str, path: str | None, task_json: str, run: int, build_model: ModelBuilder | None
) -> str:
    """Runs in a worker process: one episode, returned as its JSON line."""
    config = json.loads(job)
    office = load_office(path)
    key = f"{config['method']}|{config['reasoner']}|{path}"
    if key not in _WORKER:
        _WORKER[key] = MethodBuilder(
            MethodSpec(config["method"], config["reasoner"]),
            office,
            Settings(),
            build_model=build_model,
        )
    builder = _WORKER[key]
    task = Task.model_validate_json(task_json)
    wall_s = builder.settings.instruction_wall_s
    episode = asyncio.run(
        run_episode(task, run, builder.office, builder, config["max_steps"], wall_s=wall_s)
    )
    return episode.model_dump_json()
