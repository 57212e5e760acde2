"""The processes a process has started and not yet seen end, read from Linux's /proc."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

PROC = Path("/proc")


@dataclass(frozen=True)
class Child:
    pid: int
    command: str


def _parents() -> dict[int, list[int]]:
    """Parent pid -> the pids of its running (not zombie) children."""
    children: dict[int, list[int]] = {}
    for stat in PROC.glob("[0-9]*/stat"):
        try:
            text = stat.read_text()
        except OSError:  # ended while we looked
            continue
        # "pid (command) state ppid ...": the command may hold spaces and parentheses.
        state, ppid = text.rsplit(")", 1)[1].split()[:2]
        if state != "Z":
            children.setdefault(int(ppid), []).append(int(stat.parent.name))
    return children


def _command(pid: int) -> str:
    try:
        raw = (PROC / str(pid) / "cmdline").read_bytes()
    except OSError:
        return "?"
    return raw.replace(b"\0", b" ").decode(errors="replace").strip()


def descendants(pid: int) -> list[Child]:
    """Every running process below ``pid``: its children, theirs, and so on."""
    parents = _parents()
    found: list[Child] = []
    todo = list(parents.get(pid, []))
    while todo:
        child = todo.pop()
        found.append(Child(child, _command(child)))
        todo += parents.get(child, [])
    return found


def still_running(pids: list[int]) -> list[int]:
    """Those of ``pids`` still running (a zombie has ended)."""
    alive = []
    for pid in pids:
        try:
            state = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
        except OSError:
            continue
        if state != "Z":
            alive.append(pid)
    return alive
