"""The generator on offices where a category cannot be reached (large generated offices)."""

from __future__ import annotations

import random

from assistantx.core.office import DEFAULT_OFFICE, load_office
from assistantx.evaluation.dataset import load_base_instructions
from assistantx.evaluation.dataset.generate import _pick_round_robin


def test_a_category_no_base_reaches_gives_no_variants_instead_of_crashing() -> None:
    office = load_office()
    bases = load_base_instructions(DEFAULT_OFFICE.parent / "base_instructions.yaml", office)
    pools: dict = {b.id: {"L1": []} for b in bases}  # nobody has an L3 variant
    assert _pick_round_robin(bases, office, pools, "L3", 25, random.Random(0)) == []
