"""Right formulas in coordinates of so(n) other than the documented ones (the entries above the
diagonal row by row, as in other_conventions.py), but without hat_n: the suite cannot learn the
coordinates, checks vee_n and so4_bracket_R6 in the documented ones, and their failures say that a
change of coordinates, not the formula, is the matter, and how to fix it (give hat_n too)."""
import other_conventions
from other_conventions import vee_n, so4_bracket_R6  # noqa: F401

description = "so(n) coordinates row by row without hat_n (examples/students/conventions_without_hat.py)"
