"""zdg: exact digital geometry (the C++ library zdg, bound with pybind11).

Integers are exact (Python ints of any size; entry points escalate int64 -> int128 -> BigInt
and say which type served), numpy arrays go in and out without copies where the layout allows,
and long computations release the GIL. Errors: ValueError (bad argument), OSError (files),
OverflowError (never from an exact entry point).
"""
import html as _html
import os as _os
from collections.abc import Mapping as _Mapping

from . import _zdg
from ._zdg import (betti_numbers, cf, chamfer_transform, christoffel, connected_components, contour, converge, convex_check,
                   dag_ray_hits, hull,
                   hull_disc, hull_ellipse, hull_halfplanes, distance_transform, dsl_subsegment, floor_sum,
                   ii_curvature, local_thickness, mesh_html, motion_check, power_map, probe_plane, read_volume, recognize_dss,
                   reconstruct, recognize_plane, reduced_medial_axis, reverse_distance_transform, simple_points, sturmian,
                   surface,
                   surfels, tangential_cover, thinning, voronoi_map, voxel_dag, write_volume)

__all__ = ["betti_numbers", "cf", "chamfer_transform", "christoffel", "connected_components", "contour", "converge", "convex_check",
           "hull",
           "hull_disc", "hull_ellipse", "hull_halfplanes", "power_map", "probe_plane", "recognize_plane", "skeleton",
           "simple_points", "sturmian", "surface",
           "distance_transform", "dsl_subsegment", "floor_sum", "ii_curvature", "local_thickness", "mesh_html", "motion_check", "plot",
           "reduced_medial_axis", "reverse_distance_transform", "voronoi_map",
           "read_volume", "reconstruct", "recognize_dss", "surfels", "tangential_cover", "thinning",
           "view", "Viewer", "write_volume", "voxel_dag", "dag_ray_hits"]


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


class Viewer:
    """The viewer page of a mesh (zdg.view): the self-contained WebGL page of `zdg surface
    --html` (field menu, colour map and range, picking, layers; no network). `html` is the
    page's text; a Jupyter output shows it inline (`_repr_html_`: an iframe whose srcdoc holds
    the page, so its scripts and `window.zdgViewer` stay inside the frame); `save` writes it."""

    def __init__(self, page, faces, fields, title):
        self._html = page
        self.faces = faces
        self.fields = tuple(fields)
        self.title = title
        self.width = "100%"  # of the inline frame (CSS lengths)
        self.height = "520px"

    @property
    def html(self):
        """The page's text (a full HTML document)."""
        return self._html

    def _repr_html_(self):
        style = _html.escape(f"width:{self.width};height:{self.height};border:1px solid #ccc",
                             quote=True)
        return ('<iframe class="zdg-viewer" srcdoc="' + _html.escape(self._html, quote=True)
                + '" title="' + _html.escape(self.title, quote=True) + f'" style="{style}" '
                'sandbox="allow-scripts"></iframe>')

    def save(self, path, force=False):
        """Writes the page to `path` (an .html file) atomically: a staging file in the same
        folder renamed in place, so a reader never sees half a page. An existing file is kept
        (FileExistsError) unless force=True. Returns path."""
        name = _os.fsdecode(path)
        if not name.lower().endswith(".html"):
            raise ValueError(f"{name}: the viewer page is an .html file")
        if not force and _os.path.lexists(path):
            raise FileExistsError(f"{name}: exists (pass force=True to replace it)")
        _zdg._write_text(path, self._html, force=force)
        return path

    def __repr__(self):
        return f"<zdg.Viewer {self.title!r}: {self.faces} faces, fields {list(self.fields)}>"


def view(obj, field=None, title=None, max_faces=None):
    """The viewer page of a mesh, as a Viewer (shown inline by Jupyter; .save(path), .html).

    obj: the result of zdg.surface (its 'vertices', 'faces', the per-face 'fields' and the
    'face_normals'), a dict with those keys ('fields' and 'face_normals' optional), or a tuple
    (vertices, faces[, fields[, face_normals]]): vertices (V, 3) numbers, faces (F, k >= 3)
    vertex indices counter-clockwise from outside, fields {name: (F,) numbers} (non-finite
    values are drawn as 'no value'), face normals (F, 3). field: the field shown first (the
    first one by default); title: the page's title ('zdg view'); at most max_faces faces (None:
    the page's own limit, 2,000,000).
    The arrays are converted in C++ (zdg.mesh_html); bad input (shapes, indices out of range,
    non-finite vertices or normals, too many faces, an unknown field) raises ValueError."""
    if isinstance(obj, _Mapping):
        missing = [k for k in ("vertices", "faces") if k not in obj]
        if missing:
            raise ValueError(f"view: the mesh dict has no {' or '.join(repr(k) for k in missing)}"
                             f" (keys: {', '.join(map(str, obj))})")
        parts = (obj["vertices"], obj["faces"], obj.get("fields"), obj.get("face_normals"))
    elif isinstance(obj, tuple) and 2 <= len(obj) <= 4:
        parts = tuple(obj) + (None,) * (4 - len(obj))
    else:
        raise TypeError("view: expected the result of zdg.surface, a mesh dict {'vertices', "
                        "'faces', 'fields', 'face_normals'} or a tuple (vertices, faces[, fields"
                        f"[, face_normals]]), got {type(obj).__name__}")
    vertices, faces, fields, normals = parts
    if fields is not None and not isinstance(fields, dict):
        fields = dict(fields)
    title = "zdg view" if title is None else str(title)
    limit = {} if max_faces is None else {"max_faces": max_faces}
    page = mesh_html(vertices, faces, fields, normals, title=title,
                     field="" if field is None else str(field), **limit)
    import numpy as np
    return Viewer(page, int(np.shape(faces)[0]), list(fields or ()), title)
