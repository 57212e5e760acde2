"""A service asked for in the causative: "get my report laminated", "have the contract
shredded", "I need my file bound". English asks for work done on a thing by naming the thing
after "get"/"have"/"need"/"want" and the work's past participle after it; where that work is
one of English's services (``service_command.english_service_verbs``, irregular participles
too: "bound" is "bind") and no operation of this office runs it, it is declined like the
imperative "laminate my report" (``screen.service``), never read as handing the thing over.

Only a definite thing counts ("my report", "the contract"): "get me a book bound in red" and
"find a book bound in red" describe a thing to fetch ("bound" its adjective), and a verb
with a recipient after it ("get me ...") fetches, never has work done."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.service_command import english_service_verbs
from assistantx.core import language

# the verbs that have work done on their object: "get it done", "have it done"
_CAUSING = frozenset({"get", "have", "need", "want"})
# what opens a definite object: the requester's thing, or one pointed at
_DEFINITE = frozenset({"my", "our", "the", "this", "these", "that", "those", "it", "them"})
# how many words a thing's name may run to between its opener and the participle
_NAME_WORDS = 3


def causative_service(terms: Terms, words: list[str], at: int) -> str | None:
    """The service's verb ("laminate", "bind") when the words from ``at`` ask for it in the
    causative and nothing in this office runs it; None otherwise."""
    n = _participle_at(words, at)
    return None if n is None else _unoffered(terms, words[n])


def joined_service(terms: Terms, before: list[str], before_at: int, words: list[str]) -> str | None:
    """The service's verb of a participle that opens a part joined to a causative before it
    ("get my form stamped | and then scanned", "I need it printed | and laminated"), when
    nothing in this office runs it: the part has no verb of its own, so its work is asked of
    the same thing; before, the office's half was done and the other dropped unsaid. A part
    after a plain statement ("I printed it and scanned it") is none of this."""
    if _participle_at(before, before_at) is None:
        return None
    k = 0
    while k < len(words) and words[k] in _JOINS:
        k += 1
    if k >= len(words) or not language.is_past_participle(words[k]):
        return None
    return _unoffered(terms, words[k])


# the words between the joined parts' "and" and the second participle: "and then scanned"
_JOINS = frozenset({"then", "also", "and", "after", "afterwards"})


def _participle_at(words: list[str], at: int) -> int | None:
    """Where the work's past participle stands when the words from ``at`` ask for work in
    the causative ("get my report *laminated*"); None when they do not."""
    if 0 < at < len(words) and words[at] in _DEFINITE and words[at - 1] in _CAUSING:
        at -= 1  # "I need my file bound": "need" is a lead-in of the request's verb
    if at + 2 >= len(words) or not language.verb_lemmas(words[at]) & _CAUSING:
        return None
    if words[at + 1] not in _DEFINITE:
        return None  # "get me a ...", "get a ...": a thing to fetch
    first = at + 1 if words[at + 1] in ("it", "them") else at + 2
    for n in range(first + 1, min(first + 1 + _NAME_WORDS, len(words))):
        if language.is_past_participle(words[n]):
            return n
    return None


def _unoffered(terms: Terms, participle: str) -> str | None:
    """The English service a participle names when this office does not run it."""
    lemmas = language.verb_lemmas(participle)
    if participle in terms.service_verbs or lemmas & terms.service_verb_words:
        return None  # the office runs it ("get my file printed", "stamped"): a request
    services = sorted(lemmas & english_service_verbs())
    # "get my file fixed up"? no service of English's: not ours to say
    return services[0] if services else None
