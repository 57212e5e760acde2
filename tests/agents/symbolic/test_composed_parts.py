"""Compositions real offices need (issue 23, fix14c), on the studio office: an operation that
makes a product from the requester's item kept at a facility (a roll of film in the picture
archive or the fridge, developed in the darkroom), and a signature followed by another part
on the same paper (couriered outside, or stamped). The embedded reasoner, case by case: who
was asked, the hand-overs in order, who ends up holding what, what went out and what the
courier was told."""

from __future__ import annotations

from symbolic_run import Run, run_instruction

from assistantx.sim.world import LOCKER
from helpers.studio import studio

DEVELOP_MY_FILM = "Please develop my film."
SIGN_THEN_COURIER = "Get my drawings signed by Dr. Osei, then courier them to Harlow & Sons."
SIGN_THEN_STAMP = "Get my drawings signed by Amara Osei and then stamped."


def _asked(run: Run) -> list[str]:
    """Everyone asked something, in order (the requester's own chat left out)."""
    return [
        r.action.contact
        for r in run.stm.trace.actions()
        if r.action.type == "inquire" and r.action.contact != run.stm.requester
    ]


def _moves(run: Run) -> list[tuple[str, str | None, str, str]]:
    """Every hand-over of the world: (item, from, to, by)."""
    return [
        (e.detail["item"], e.detail["frm"], e.detail["to"], e.detail["by"])
        for e in run.sim.world.handovers()
    ]


async def test_a_film_kept_in_the_archive_is_taken_out_by_its_keeper_and_comes_back_to_you() -> (
    None
):
    run = await run_instruction(studio(), "ada", DEVELOP_MY_FILM)
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    assert _asked(run) == ["pia", "otto"]  # the darkroom's nearer guard, the archive's keeper
    assert _moves(run) == [
        ("film:ada", "store_room", LOCKER, "otto"),
        ("film:ada", LOCKER, "ada", "ada"),
        ("photo_prints:ada", LOCKER, "ada", "ada"),
    ]
    world = run.sim.world
    assert world.check({"copied": "film:ada"}) and "photo_prints:ada" in world.made
    assert not [r for r in run.stm.trace.actions() if r.refused]  # the keeper collects nothing


async def test_a_film_in_the_fridge_goes_back_to_its_owner_and_the_prints_to_the_one_named() -> (
    None
):
    run = await run_instruction(
        studio(), "bo", "Could you develop my film and take the prints to Cyrus?"
    )
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    assert set(_asked(run)) == {"pia", "kai", "cyrus"}
    moves = _moves(run)
    assert moves[0] == ("film:bo", "store_room", LOCKER, "kai")
    assert set(moves[1:]) == {
        ("film:bo", LOCKER, "bo", "bo"),
        ("photo_prints:bo", LOCKER, "cyrus", "cyrus"),
    }


async def test_a_film_on_its_owners_desk_is_put_in_by_its_owner() -> None:
    run = await run_instruction(studio(), "cyrus", "develop my film please")
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    assert _asked(run) == ["pia"]  # no keeper to ask
    assert _moves(run)[0] == ("film:cyrus", "cyrus", LOCKER, "cyrus")


async def test_signed_drawings_are_couriered_out_and_the_courier_is_told_where() -> None:
    run = await run_instruction(studio(), "ada", SIGN_THEN_COURIER)
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    assert _asked(run) == ["amara", "luc"]
    world = run.sim.world
    assert world.check({"signed": ["drawings:ada", "amara"]})
    assert world.holder["drawings:ada"] == "front_desk"  # gone out from the post desk
    [sent] = world.sent_out()
    assert sent.detail["item"] == "drawings:ada" and sent.detail["by"] == "luc"
    assert "Harlow & Sons" in sent.detail["told"]
    # signed before it went out: the signature's hand-over comes first
    signed_at = next(e.time for e in world.log if e.kind == "signed")
    assert signed_at <= sent.time
    assert "couriered to Harlow & Sons" in run.stm.trace.summary


async def test_with_the_signer_away_no_unsigned_drawing_goes_out() -> None:
    run = await run_instruction(studio(), "ada", SIGN_THEN_COURIER, unavailable=("amara",))
    assert run.stm.trace.outcome == "unachievable", run.stm.trace.summary
    assert _moves(run) == [] and run.sim.world.sent_out() == []
    assert "luc" not in _asked(run)  # the courier is not troubled for a task that cannot be
    assert (
        "courier your drawing set to Harlow & Sons "  # where it goes, not "for you"
        "(it was to follow: get your drawing set signed by Amara Osei)"
    ) in run.stm.trace.summary


async def test_signed_then_stamped_drawings_end_with_the_requester() -> None:
    run = await run_instruction(studio(), "ada", SIGN_THEN_STAMP)
    assert run.stm.trace.outcome == "done", run.stm.trace.summary
    world = run.sim.world
    assert world.check({"signed": ["drawings:ada", "amara"]})
    assert world.check({"sealed": "drawings:ada"})
    assert world.holder["drawings:ada"] == "ada"
    kinds = [e.kind for e in world.log if e.kind in ("signed", "sealed")]
    assert kinds == ["signed", "sealed"]
