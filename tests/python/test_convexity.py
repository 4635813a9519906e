"""Digital convexity from Python (zdg.convex_check, the operation of zdg convex check): worked
examples of the definition (Lachaud 2022), coordinates past 64 bits, bad arguments."""
import pytest

import zdg


def test_knight_pair_is_h_convex_but_not_fully_convex():
    r = zdg.convex_check([(0, 0), (2, 1)])
    assert r["convex"] is False and r["definition"] == "full" and r["points"] == 2
    # The segment crosses the edge {1} x (0, 1), whose vertices are not in the set.
    assert r["witness"]["dimension"] == 1
    assert r["witness"]["khalimsky"] == [2, 1]
    assert r["witness"]["vertices"] == [(1, 0), (1, 1)]
    assert zdg.convex_check([(0, 0), (2, 1)], definition="hull")["convex"] is True
    assert "witness" not in zdg.convex_check([(0, 0), (1, 1)])


def test_hole_and_3d_and_past_64_bits():
    ring = [(x, y) for x in range(3) for y in range(3) if (x, y) != (1, 1)]
    r = zdg.convex_check(ring, definition="hull")
    assert r["convex"] is False and r["witness"]["point"] == (1, 1)
    big = 10**30
    cube = [(x, y, z + big) for x in (0, 1) for y in (0, 1) for z in (0, 1)]
    r = zdg.convex_check(cube)
    assert r["convex"] is True and r["dimension"] == 3 and r["integer_type"] != "int64"


def test_bad_arguments():
    with pytest.raises(ValueError):
        zdg.convex_check([(0, 0)], definition="strict")
    with pytest.raises(ValueError):
        zdg.convex_check([(0, 0), (1, 2, 3)])
    with pytest.raises(ValueError):
        zdg.convex_check([(0, 0), (10**12, 1)], definition="hull", max_columns=10)
