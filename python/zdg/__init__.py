"""zdg: exact digital geometry (the C++ library zdg, bound with pybind11).

Integers are exact (Python ints of any size; entry points escalate int64 -> int128 -> BigInt
and say which type served), numpy arrays go in and out without copies where the layout allows,
and long computations release the GIL. Errors: ValueError (bad argument), OSError (files),
OverflowError (never from an exact entry point).
"""
from ._zdg import (betti_numbers, cf, christoffel, connected_components, contour, converge, hull,
                   hull_disc, hull_ellipse, hull_halfplanes, distance_transform, dsl_subsegment, floor_sum,
                   ii_curvature, power_map, probe_plane, read_volume, recognize_dss,
                   recognize_plane, reduced_medial_axis, reverse_distance_transform, simple_points, surface,
                   surfels, tangential_cover, thinning, voronoi_map, write_volume)

__all__ = ["betti_numbers", "cf", "christoffel", "connected_components", "contour", "converge",
           "hull",
           "hull_disc", "hull_ellipse", "hull_halfplanes", "power_map", "probe_plane", "recognize_plane", "skeleton",
           "simple_points", "surface",
           "distance_transform", "dsl_subsegment", "floor_sum", "ii_curvature", "plot",
           "reduced_medial_axis", "reverse_distance_transform", "voronoi_map",
           "read_volume", "recognize_dss", "surfels", "tangential_cover", "thinning",
           "write_volume"]


def skeleton(image, method="critical-kernel", skeleton="curve", adjacency=None, threads=0):
    """The skeleton of the object of a 2D or 3D binary image: `thinning` with a curve
    skeleton by default ('ultimate', 'curve' or 'surface'; methods 'critical-kernel',
    parallel, Bertrand and Couprie, or 'sequential'). Returns a uint8 array of the image's
    shape (1 on the skeleton); the topology of the object is kept."""
    return thinning(image, method=method, skeleton=skeleton, adjacency=adjacency,
                    threads=threads)


def plot(result, norm="linf", ax=None):
    """Log-log plot of a converge() result: the error in `norm` ('linf', 'l2', 'mean')
    against h, one curve per (shape, estimator). Needs matplotlib; returns the axes."""
    if ax is None:
        import matplotlib.pyplot as plt
        ax = plt.figure().add_subplot()
    curves = {}
    for r in result["runs"]:
        key = (r["shape"], r["estimator"])
        per_h = curves.setdefault(key, {})
        # Over translations: the worst case for linf, the average otherwise (as the fits).
        per_h.setdefault(r["h"], []).append(r[norm])
    for (shape, estimator), per_h in curves.items():
        hs = sorted(per_h)
        agg = max if norm == "linf" else (lambda v: sum(v) / len(v))
        ax.loglog(hs, [agg(per_h[h]) for h in hs], "o-", label=f"{estimator} on {shape}")
    ax.set_xlabel("h")
    ax.set_ylabel(f"{norm} error")
    ax.legend()
    return ax
