"""plans bench shows how drawing grows with the number of groups (issue 21): chains of RRR dyads."""

import pytest

pytest.importorskip("mpmath")

from plans.bench.cases import CHAIN_DYADS, dyad_chain_toml  # noqa: E402
from plans.bench.run import DEFAULT, QUICK, BenchResult, _targets, markdown  # noqa: E402
from plans.scene import loads  # noqa: E402
from plans.structure import find_structure  # noqa: E402


def test_the_chain_is_a_crank_and_n_rrr_dyads():
    structure = find_structure(loads(dyad_chain_toml(3)))
    assert structure.formula == "I(1,2) → RRR(3,4) → RRR(5,6) → RRR(7,8)"


def test_the_full_bench_times_the_chains_and_the_quick_one_does_not():
    assert DEFAULT.chains == CHAIN_DYADS == (5, 20, 50)
    assert QUICK.chains == ()


@pytest.mark.parametrize("seconds, met", [(6.1, True), (12.0, False)])
def test_the_chains_are_reported_with_the_target_for_fifty_dyads(seconds, met):
    chains = {5: 1.5, 20: 2.4, 50: seconds}
    targets = _targets([], {}, {}, chains=chains)
    (target,) = [t for t in targets if "50 RRR dyads" in t.name]
    assert target.goal == "< 10 s" and target.met is met and target.measured == f"{seconds:.1f} s"
    text = markdown(BenchResult("here", DEFAULT, [], targets, chains=chains))
    assert f"n = 5: 1.50 s; n = 20: 2.40 s; n = 50: {seconds:.2f} s." in text
