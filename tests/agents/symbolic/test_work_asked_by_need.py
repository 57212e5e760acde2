"""A colleague's work a paper needs, or that they have not done yet, said before a request
that names nothing else ("my affidavit needs Tomasz's sworn stamp before it goes to the
client, can you sort that?", "Dr Hartley still hasn't signed the new policy. Can you take my
copy to him and bring it back once he has?") is that work by them on the requester's paper
(blind rounds 34-36's class: nothing was done, or a photocopy was handed over). A statement
alone, or beside a request for another thing, is context as before."""

from __future__ import annotations

import pytest

from assistantx.core.office import load_office
from helpers.notary_office import notary_office
from helpers.reading import frame_reader

_frame = frame_reader(notary_office, "ruth")


@pytest.mark.parametrize(
    ("text", "kind", "item", "actor"),
    [
        (
            "my affidavit needs Tomasz's sworn stamp before it goes to the client, can you "
            "sort that?",
            "seal",
            "affidavit",
            "tomasz",
        ),
        (
            "my affidavit needs Tomasz's wet signature, can you sort that?",
            "sign",
            "affidavit",
            "tomasz",
        ),
        (
            "my affidavit needs Hana's official stamp, could you arrange that?",
            "seal",
            "affidavit",
            "hana",
        ),
        (
            "my letter needs stamping by Hana before it goes to the client, can you handle it?",
            "seal",
            "document",
            "hana",
        ),
        (
            "Tomasz still hasn't signed my affidavit. Can you take it to him and bring it back "
            "once he has?",
            "sign",
            "affidavit",
            "tomasz",
        ),
        (
            "Dr Hartley still hasn't signed the new policy. Can you take my copy to him and "
            "bring it back once he has?",
            "sign",
            "document",
            "felix",
        ),
        (
            "Dr Hartley hasn't signed the policy yet, could you take mine over to him?",
            "sign",
            "document",
            "felix",
        ),
        (
            "Tomasz hasn't stamped my letter yet, can you get that done?",
            "seal",
            "document",
            "tomasz",
        ),
        (
            "Hana has not yet stamped my contract - could you sort that out?",
            "seal",
            "document",
            "hana",
        ),
    ],
)
def test_the_work_is_done_by_them_on_the_requesters_paper(
    text: str, kind: str, item: str, actor: str
) -> None:
    frame = _frame(text)
    assert frame.decline is None and frame.question is None, frame
    assert [(t.kind, t.item, t.owner, t.actor, t.recipient) for t in frame.tasks] == [
        (kind, item, "ruth", actor, "ruth")
    ], frame


def test_a_statement_alone_moves_nothing() -> None:
    frame = _frame("Tomasz still hasn't signed my affidavit.")
    assert frame.tasks == [], frame


@pytest.mark.parametrize(
    ("text", "kind", "item"),
    [
        (
            "Tomasz hasn't signed my affidavit yet, could you bring me Hana's stapler",
            "transfer",
            "stapler",
        ),
        (
            "Dr Hartley still hasn't signed the new policy, can you make me a copy of it",
            "copy",
            "document",
        ),
    ],
)
def test_beside_a_request_for_another_thing_it_is_context(text: str, kind: str, item: str) -> None:
    frame = _frame(text)
    assert [(t.kind, t.item) for t in frame.tasks] == [(kind, item)], frame


def test_a_paper_taken_to_a_colleague_for_nothing_is_a_hand_over() -> None:
    frame = _frame("take my affidavit to Tomasz")
    assert [(t.kind, t.item, t.recipient) for t in frame.tasks] == [
        ("transfer", "affidavit", "tomasz")
    ], frame


def test_the_client_after_a_plain_hand_over_is_still_asked_about() -> None:
    frame = _frame("take my letter to the client")
    assert frame.question is not None and "client" in frame.question, frame


@pytest.mark.parametrize(
    "text",
    [
        "Zhang still hasn't signed the new travel policy. Can you take my copy to him and bring "
        "it back once he has?",
        "Zhang still hasn't signed the new travel policy, take my copy to him",
    ],
)
def test_a_paper_the_office_names_otherwise_is_its_one_paper_to_sign(text: str) -> None:
    """Blind round 34 after its fixes: "the new fire safety policy" is no name the office
    gives its paper, so the work was not read and a photocopy was made and handed to the
    signer (a wrong physical action). The work is on a paper one signs; an office with one
    such paper means it."""
    frame = frame_reader(load_office, "lee")(text)
    assert [(t.kind, t.owner, t.actor, t.recipient) for t in frame.tasks] == [
        ("sign", "lee", "zhang", "lee")
    ], frame
