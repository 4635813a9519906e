"""Exact arithmetic on Python ints: results checked against Python's own exact arithmetic
(fractions, integer division), beyond 2^128 included."""
import subprocess
import sys
from fractions import Fraction
from math import gcd

import pytest

import zdg

hyp = pytest.importorskip("hypothesis")
from hypothesis import given, strategies as st  # noqa: E402

big = st.integers(min_value=-(2**300), max_value=2**300)
positive_big = st.integers(min_value=1, max_value=2**300)


@given(big, positive_big)
def test_cf_terms_evaluate_back_to_the_fraction(p, q):
    """Theorem: [a0; a1, ..., an] = p/q, and the last convergent is p/q in lowest terms."""
    r = zdg.cf(p, q)
    x = Fraction(r["terms"][-1])
    for a in reversed(r["terms"][:-1]):
        x = a + 1 / x
    assert x == Fraction(p, q)
    last = r["convergents"][-1]
    assert Fraction(*last) == Fraction(p, q) and gcd(*last) == 1
    # Partial quotients after the first are positive (Euclid's algorithm).
    assert all(a >= 1 for a in r["terms"][1:])


def test_cf_says_which_integer_type_served():
    assert zdg.cf(355, 113) == {"terms": [3, 7, 16],
                                "convergents": [(3, 1), (22, 7), (355, 113)],
                                "integer_type": "int64"}
    assert zdg.cf(2**100 + 1, 2**99 + 7)["integer_type"] == "int128"
    r = zdg.cf(3**200, 2**300 + 1)
    assert r["integer_type"] == "bigint"
    assert Fraction(*r["convergents"][-1]) == Fraction(3**200, 2**300 + 1)


@given(st.integers(0, 200), st.integers(1, 200))
def test_christoffel_word_counts_ones_by_floor(p, q):
    """Convention (DESIGN.md): the prefix of length k of the lower word holds
    floor(k p' / (p' + q')) ones, p'/q' = p/q reduced; the upper word is its reverse."""
    g = gcd(p, q)
    pr, qr = p // g, q // g
    r = zdg.christoffel(p, q)
    w = r["word"]
    assert (r["p"], r["q"]) == (pr, qr) and len(w) == pr + qr
    for k in range(len(w) + 1):
        assert w[:k].count("1") == k * pr // (pr + qr)
    assert zdg.christoffel(p, q, upper=True)["word"] == w[::-1]
    if pr > 0:
        u, v = r["standard_factorization"]
        assert u + v == w
        (lp, lq), (rp, rq) = r["parents"]
        # Stern-Brocot parents: mediant and unimodularity.
        assert (lp + rp, lq + rq) == (pr, qr) and rp * lq - lp * rq == 1


def test_christoffel_huge_slope_without_word():
    p, q = 2**200 + 1, 2**199 + 3
    r = zdg.christoffel(p, q, word=False)
    assert r["word"] is None and r["integer_type"] == "bigint"
    (lp, lq), (rp, rq) = r["parents"]
    assert (lp + rp, lq + rq) == (p, q) and rp * lq - lp * rq == 1


@given(st.integers(0, 60), st.integers(-50, 50).filter(lambda m: m != 0), st.integers(-10**6, 10**6),
       st.integers(-10**6, 10**6))
def test_floor_sum_equals_the_sum(n, m, a, b):
    assert zdg.floor_sum(n, m, a, b)["value"] == sum((a * i + b) // m for i in range(n))


@given(st.integers(0, 2**70), positive_big, big, big)
def test_floor_sum_closed_form_on_big_ints(n, m, a, b):
    """sum_{i<n} floor((a i + b)/m) for a multiple of m is exact: take a = m a', b = m b'."""
    r = zdg.floor_sum(n, m, m * a, m * b)["value"]
    assert r == a * n * (n - 1) // 2 + b * n


def dsl_points(a, b, mu, x0, n):
    """The naive DSL mu <= a x - b y < mu + b (0 <= a < b) over x0 .. x0 + n - 1."""
    return [(x, (a * x - mu) // b) for x in range(x0, x0 + n)]


@given(st.integers(0, 40), st.integers(1, 40), st.integers(-100, 100), st.integers(-10**40, 10**40),
       st.integers(1, 60))
def test_dss_recognition_of_dsl_points(a, b, mu, x0, n):
    """Points of a naive DSL form a DSS whose characteristics contain every point tightly,
    and dsl_subsegment agrees with the recognizer on the enumerated points."""
    if a >= b:
        a, b = b - 1 if b > 1 else 0, b
    pts = dsl_points(a, b, mu, x0, n)
    r = zdg.recognize_dss(pts)
    assert r["is_dss"] and r["longest_prefix"] == n
    rem = [r["a"] * x - r["b"] * y for x, y in pts]
    assert min(rem) == r["mu"] and max(rem) < r["mu"] + r["omega"]
    if n > 1:
        s = zdg.dsl_subsegment(a, b, mu, x0, x0 + n - 1)
        assert (s["a"], s["b"], s["mu"]) == (r["a"], r["b"], r["mu"])


def test_not_a_dss_reports_the_longest_prefix():
    r = zdg.recognize_dss([(0, 0), (1, 0), (2, 0), (3, 1), (4, 1), (5, 2), (6, 2), (7, 2), (8, 2)])
    assert not r["is_dss"] and 2 <= r["longest_prefix"] < 9


@given(st.lists(st.sampled_from([(1, 0), (0, 1), (1, 1), (1, -1)]), min_size=1,
                max_size=40))
def test_tangential_cover_segments_are_maximal_dss(steps):
    """Every segment of the cover is a DSS and cannot be extended by the next or the previous
    point of the (open) curve; together they cover the curve."""
    pts = [(0, 0)]
    for dx, dy in steps:
        pts.append((pts[-1][0] + dx, pts[-1][1] + dy))
    segs = zdg.tangential_cover(pts, closed=False, connectivity=8)
    covered = set()
    for s in segs:
        part = pts[s["begin"]:s["end"] + 1]
        assert len(part) == s["length"]
        r = zdg.recognize_dss(part, connectivity=8)
        assert r["is_dss"] and (r["a"], r["b"]) == (s["a"], s["b"])
        if s["end"] + 1 < len(pts):
            assert not zdg.recognize_dss(part + [pts[s["end"] + 1]], connectivity=8)["is_dss"]
        if s["begin"] > 0:
            assert not zdg.recognize_dss([pts[s["begin"] - 1]] + part, connectivity=8)["is_dss"]
        covered.update(range(s["begin"], s["end"] + 1))
    assert covered == set(range(len(pts)))


def test_bad_input_raises_the_mapped_exceptions():
    with pytest.raises(ValueError, match="zero denominator"):
        zdg.cf(1, 0)
    with pytest.raises(ValueError, match="p >= 0 and q > 0"):
        zdg.christoffel(-1, 2)
    with pytest.raises(ValueError, match="must be >= 0"):
        zdg.floor_sum(-1, 1, 1, 1)
    with pytest.raises(ValueError, match="not 8-adjacent|adjacent"):
        zdg.recognize_dss([(0, 0), (5, 5)])
    with pytest.raises(TypeError):
        zdg.cf(1.5, 2)
    with pytest.raises(TypeError):
        zdg.cf(True, 2)


@given(st.lists(st.tuples(big, big), min_size=1, max_size=30))
def test_hull_vertices_are_a_convex_polygon_containing_the_points(points):
    """Vertices are input points, strictly convex and counter-clockwise, and every input point
    lies on the left of (or on) every edge: checked with Python's exact integers."""
    r = zdg.hull(points)
    v = r["vertices"]
    assert all(p in points for p in v)

    def orient(a, b, c):
        return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])

    if len(v) >= 3:
        for i in range(len(v)):
            a, b, c = v[i], v[(i + 1) % len(v)], v[(i + 2) % len(v)]
            assert orient(a, b, c) > 0
            assert all(orient(a, b, p) >= 0 for p in points)
    else:
        assert all(orient(v[0], v[-1], p) == 0 for p in points)


def test_gmp_out_of_memory_is_memory_error():
    """Issue #41: a failed GMP allocation raises MemoryError (zdg installs GMP's allocation
    functions) instead of aborting the interpreter. In a child interpreter under RLIMIT_AS: the
    convergents of a 200,000-bit fraction need gigabytes (their sizes add up quadratically)."""
    code = (
        "import os, random, resource, zdg\n"
        "rng = random.Random(41)\n"
        "p, q = rng.getrandbits(200000) | 1, rng.getrandbits(199990) | 1\n"
        "pages = int(open('/proc/self/statm').read().split()[0])\n"
        "limit = pages * os.sysconf('SC_PAGE_SIZE') + (256 << 20)\n"
        "resource.setrlimit(resource.RLIMIT_AS, (limit, limit))\n"
        "try:\n"
        "    zdg.cf(p, q)\n"
        "    print('no error')\n"
        "except MemoryError:\n"
        "    print('memory error')\n"
        "assert zdg.cf(415, 93)['terms'] == [4, 2, 6, 7]\n"
        "print('alive')\n")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, (r.returncode, r.stderr)
    assert "GNU MP" not in r.stderr
    assert r.stdout.split() == ["memory", "error", "alive"], r.stdout


@given(st.integers(-40, 40), st.integers(-5, 5).filter(lambda b: b != 0),
       st.integers(2, 300).filter(lambda d: int(d**0.5) ** 2 != d and (int(d**0.5) + 1) ** 2 != d),
       st.integers(-30, 30).filter(lambda c: c != 0))
def test_sturmian_word_is_the_floor_difference(a, b, d, c):
    """The characteristic word of frac(x) letter by letter from floor((n+1) alpha) - floor(n
    alpha), computed here with Python's exact integer square root."""
    from math import isqrt
    r = zdg.sturmian(a, b, d, c, length=60)
    P, D, Q = r["surd"]

    def floor_k(k):  # floor(k (P + sqrt D) / Q) for k >= 1, exact
        s = isqrt(k * k * D)
        return (k * P + s) // Q if Q > 0 else (k * P + s + 1) // Q

    f = floor_k(1)
    assert f == r["floor"]
    word = "".join(str((floor_k(n + 1) - (n + 1) * f) - (floor_k(n) - n * f)) for n in range(1, 61))
    assert r["word"] == word
    for p, q in r["christoffel_convergents"]:
        assert zdg.christoffel(p, q)["word"] == "0" + word[: p + q - 2] + "1"


def _triples(limit):
    out = []
    m = 2
    while m * m < limit:
        for n in range(1, m):
            if (m - n) % 2 == 1 and gcd(m, n) == 1 and m * m + n * n < limit:
                out.append((m * m - n * n, 2 * m * n, m * m + n * n))
        m += 1
    return out


def _digitized(a, b, c, center, shift, p):
    """D(p) = floor(R (p - center) + center + shift + 1/2), in Fractions."""
    x, y = Fraction(p[0]) - center[0], Fraction(p[1]) - center[1]
    u = Fraction(a * x - b * y, 1) / c + center[0] + shift[0]
    w = Fraction(b * x + a * y, 1) / c + center[1] + shift[1]
    half = Fraction(1, 2)
    return ((u + half).__floor__(), (w + half).__floor__())


@given(st.sampled_from(_triples(300)), st.booleans(), st.sampled_from([1, -1]),
       st.tuples(st.fractions(-20, 20, max_denominator=6), st.fractions(-20, 20, max_denominator=6)))
def test_motion_check_witness_and_twin_triples(t, swap, sign, center):
    """Nouvel and Remila: bijective iff max(|a|, |b|) = c - 1; a witness pair has one image
    (checked in Fractions) and the hole has no preimage among the points within 1 of
    R^-1 (hole - v)."""
    a, b, c = t
    if swap:
        a, b = b, a
    a *= sign
    r = zdg.motion_check(a, b, c, center=center)
    assert r["period"] == c
    zero = (Fraction(0), Fraction(0))
    if center == zero:
        assert r["bijective"] == (max(abs(a), abs(b)) == c - 1)
    if r["bijective"]:
        assert r["collision"] is None and r["hole"] is None
        return
    p1, p2 = r["collision"]
    assert p1 != p2
    assert _digitized(a, b, c, center, zero, p1) == tuple(r["image"])
    assert _digitized(a, b, c, center, zero, p2) == tuple(r["image"])
    hx, hy = r["hole"]
    # R^-1 (q - v) with v = center - R center: the candidates around it.
    qx, qy = Fraction(hx) - center[0], Fraction(hy) - center[1]
    px = (a * qx + b * qy) / c + center[0]
    py = (-b * qx + a * qy) / c + center[1]
    for i in range(-2, 3):
        for j in range(-2, 3):
            p = (px.__floor__() + i, py.__floor__() + j)
            assert _digitized(a, b, c, center, zero, p) != (hx, hy)


def test_motion_check_refuses_a_non_triple():
    with pytest.raises(ValueError, match="not a Pythagorean triple"):
        zdg.motion_check(3, 4, 6)
