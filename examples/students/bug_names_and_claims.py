"""Buggy names: the energy written as `energy` (the slot is hamiltonian_3_4, named after
(3.4)) and a midpoint rule whose claims say "symmetry" (the claim is `symmetric`). Expected: a
warning naming the slot `energy` probably means, and the check UNCHECKED (exit status 1), because a
claim nothing can verify is not a pass, naming the claim it probably means and listing all of them."""
from correct import *  # noqa: F401,F403
from correct import Midpoint

description = "a slot and a claim misnamed (examples/students/bug_names_and_claims.py)"


def energy(I, P):
    return sum(p * p / i for p, i in zip(P, I)) / 2


class MidpointTypo:
    name = "midpoint_typo"
    claims = {"order": 2, "symmetry": True}
    rigid_body_step = staticmethod(Midpoint.rigid_body_step)
