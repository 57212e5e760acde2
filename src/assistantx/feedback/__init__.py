"""Feedback and impact: the after-task survey, walking saved, and the usage report.

- ``answers``: reading replies ("1 yes 2 no", "y/n/?/y", "all yes", "stop surveys", ...)
- ``survey``: the questions and one survey's state machine (answers, re-ask, reminder, expiry)
- ``walking``: the walk the requester was spared, over the map's planner
- ``impact``: one ended instruction's record (kind, outcome, durations, group requests, walk)
- ``store``: the ``feedback_*`` tables in the journal's SQLite file
- ``surveyor``: ties them to the Assistant and the messenger
- ``report``: the usage report as JSON, Markdown and PNG charts
"""

# ``assistantx.core.trace`` and ``assistantx.memory`` import each other; entering through the
# memory package is the order that resolves, so do that before any module here needs a Trace.
import assistantx.memory as _memory  # noqa: F401
