"""A facility's guard who said no in their own chat and then "I can help" in the group chat is
a yes: the newer answer wins (their yes was dropped because they had said no before, and the
errand ended unachievable). A no after the group's yes still stands, a no alone stands, and
a lender's yes is still given in their own chat (their own item leaves them)."""

from __future__ import annotations

import pytest

from assistantx.agents.symbolic.evidence import Evidence, Question
from assistantx.agents.symbolic.roles import Role, Roles
from assistantx.core.dialogue import DialogueTurn
from assistantx.core.office import load_office
from assistantx.core.ports.messenger import ChatRef

_OFFICE = load_office()
_ROLES = Roles(_OFFICE, _OFFICE.distance)
_HEAT = Role("0.doer", "heat", "lee", facility="microwave", operation="heat", item_type="lunch")
_LEND = Role("0.source", "lend", "lee", item_type="stapler")


class _Memory:
    """The long-term memory's one answer read here: nobody's item was taken for another."""

    def taken_by_another(self, item: str, instruction_id: str) -> None:
        return None


def _said(role: Role, person: str, private: tuple[float, str], group: tuple[float, str] | None):
    ev = Evidence(requester="lee", robot_place=None)
    q = Question("q1", person, False, _ROLES.question(role, person), 1.0)
    ev.questions.append(q)
    ev.replies["q1"] = [
        DialogueTurn(
            time=private[0],
            direction="in",
            chat=ChatRef(kind="dm", id=person),
            person=person,
            text=private[1],
            in_reply_to="q1",
        )
    ]
    if group is not None:
        g = Question("q2", "all", True, _ROLES.group_question(role), 2.0)
        ev.questions.append(g)
        ev.replies["q2"] = [
            DialogueTurn(
                time=group[0],
                direction="in",
                chat=ChatRef(kind="group", id="all"),
                person=person,
                text=group[1],
                in_reply_to="q2",
            )
        ]
    return ev


@pytest.mark.parametrize(
    ("role", "private", "group", "excluded"),
    [
        (_HEAT, (1.5, "Sorry, I can't help with that."), (3.0, "Yes, I can help."), False),
        (_HEAT, (3.5, "Sorry, I can't help with that."), (3.0, "Yes, I can help."), True),
        (_HEAT, (1.5, "Sorry, I can't help with that."), None, True),
        (_HEAT, (1.5, "Sorry, I can't."), (3.0, "No, sorry."), True),
        (_LEND, (1.5, "Sorry, I need it."), (3.0, "Yes, I can help."), True),
    ],
)
def test_the_newer_answer_wins(
    role: Role, private: tuple[float, str], group: tuple[float, str] | None, excluded: bool
) -> None:
    ev = _said(role, "hu", private, group)
    why = _ROLES._exclusion(role, "hu", _Memory(), ev, 10.0)  # type: ignore[arg-type]
    assert (why == "said no") is excluded, why
