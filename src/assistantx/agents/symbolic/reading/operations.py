"""After the frames: the office's operation named where several share a task's shape ("scan"
or "copy" a contract), asked about when the words do not say which, declined when none fits
the item ("charge my radio" where only headlamps are charged), and a send-out service's place
outside taken from the readings ("send out my drawing to the client") or asked for."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.destination import Outside
from assistantx.agents.symbolic.reading.lexicon import Lexed, inflections
from assistantx.core import language
from assistantx.core.office import Office, Operation
from assistantx.core.task_schema import SHAPE_KIND, Task, TaskFrame
from assistantx.core.wording import a_thing
from assistantx.memory.names import normalize

_KIND_SHAPE = {kind: shape for shape, kind in SHAPE_KIND.items()}
WHERE_TO = "Where should I "  # the question for a send-out service's place outside


class OperationChooser:
    """Names the operations of one office's tasks from the words that asked for them."""

    def __init__(self, office: Office) -> None:
        self.office = office
        self._op_words = {
            op.id: {
                form
                for phrase in (*op.verbs, op.name)
                for verb in normalize(phrase).split()[:1]
                for form in inflections(verb)
            }
            for op in office.operations
        }

    def choose(self, frame: TaskFrame, lexed: Lexed, outside: Outside | None) -> TaskFrame:
        """Name the operation where the office has several of a task's shape ("scan" or
        "copy" a contract); ask which when the words do not say."""
        words = {t.word for t in lexed.tokens}
        facility_ops = {
            op
            for m in lexed.mentions
            if m.kind == "facility"
            for op in self.office.facility(m.ids[0]).operations
        }
        tasks: list[Task] = []
        for t in frame.tasks:
            shape = _KIND_SHAPE.get(t.kind)
            ops = self.office.with_shape(shape) if shape and t.kind != "produce" else []
            if shape == "treat" and ops and t.item is not None and t.operation is None:
                # the service asked for by its verb, else at the facility named, else any
                asked = [op for op in ops if self._op_words[op.id] & words] or [
                    op for op in ops if op.id in facility_ops
                ]
                asked = asked or ops
                fits = [op for op in asked if op.input == t.item]
                if not fits:  # "charge my radio" where only headlamps are charged
                    return TaskFrame(
                        requester=frame.requester, decline=self._cannot_treat(asked, t.item)
                    )
                if len(fits) == 1 and len(ops) > 1:  # named where several share the shape
                    t = t.model_copy(update={"operation": fits[0].id})
                ops = fits
            if len(ops) > 1 and t.operation is None:
                said = [op for op in ops if self._op_words[op.id] & words]
                if not said:  # "put my contract in the scanner": the facility's own service
                    said = [op for op in ops if op.id in facility_ops]
                if len(said) != 1:
                    names = " or ".join(op.name for op in ops)
                    return TaskFrame(
                        requester=frame.requester, question=f"Which do you mean: {names}?"
                    )
                t = t.model_copy(update={"operation": said[0].id})
            op_id = t.operation or (ops[0].id if len(ops) == 1 else None)
            op = self.office.operation(op_id) if op_id else None
            if op is not None and op.sends_out and t.destination is None:
                # a fax leaves the office: where to is the requester's to say, never a guess;
                # the readings stage found the words ("send out my drawing to the client")
                where = outside.phrase if outside is not None else None
                if where is None:
                    return TaskFrame(
                        requester=frame.requester,
                        question=f"{WHERE_TO}{op.name} it to? Please give the number "
                        "or the name of the place.",
                    )
                t = t.model_copy(update={"operation": op.id, "destination": where})
            tasks.append(t)
        return frame.model_copy(update={"tasks": tasks})

    def _cannot_treat(self, ops: list[Operation], item: str) -> str:
        """Why a service the office offers cannot be run on this item, with what it is for."""
        asked = " or ".join(dict.fromkeys(op.name for op in ops))
        thing = self._item_name(item)
        fits = [
            f"{op.name} {language.plural(self._item_name(op.input))}"
            for op in ops
            if op.input is not None
        ]
        return f"Sorry, I can't {asked} {a_thing(thing)} here: I can only {' and '.join(fits)}."

    def _item_name(self, type_id: str) -> str:
        return self.office.item_type(type_id).name
