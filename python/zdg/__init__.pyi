# Type stubs of the zdg package (the extension zdg._zdg and zdg.plot).
from typing import Any, Literal, Mapping, Optional, Sequence, TypedDict, Union, overload

import os

import numpy as np
import numpy.typing as npt

StrOrBytesPath = Union[str, bytes, os.PathLike[str], os.PathLike[bytes]]
IntegerType = Literal["int64", "int128", "bigint"]

class ContinuedFraction(TypedDict):
    terms: list[int]
    convergents: list[tuple[int, int]]
    integer_type: IntegerType

class ChristoffelWord(TypedDict):
    p: int
    q: int
    word: Optional[str]
    standard_factorization: Optional[tuple[str, str]]
    parents: Optional[tuple[tuple[int, int], tuple[int, int]]]
    integer_type: IntegerType

class FloorSum(TypedDict):
    value: int
    integer_type: IntegerType

class Sturmian(TypedDict):
    surd: tuple[int, int, int]
    preperiod: list[int]
    period: list[int]
    floor: int
    word: str
    christoffel_convergents: list[tuple[int, int]]
    integer_type: IntegerType

class DssRecognition(TypedDict):
    is_dss: bool
    longest_prefix: int
    connectivity: int
    a: int
    b: int
    mu: int
    omega: int
    integer_type: IntegerType

class MaximalSegment(TypedDict):
    begin: int
    end: int
    length: int
    a: int
    b: int
    mu: int
    omega: int

class DslSubsegment(TypedDict):
    a: int
    b: int
    mu: int
    integer_type: IntegerType

class Hull(TypedDict):
    vertices: list[tuple[int, int]]
    integer_type: IntegerType

class Hull3d(TypedDict):
    dimension: int
    vertices: list[tuple[int, int, int]]
    facets: list[list[int]]
    normals: list[tuple[int, int, int]]
    volume6: int
    integer_type: IntegerType

class PlaneRecognition(TypedDict, total=False):
    is_plane: bool
    normal: tuple[int, int, int]
    mu: int
    omega: int
    integer_type: IntegerType

class PlaneProbing(TypedDict):
    normal: tuple[int, int, int]
    steps: int
    predicate_calls: int
    reduced_basis: bool
    integer_type: IntegerType

class SurfaceMesh(TypedDict):
    vertices: npt.NDArray[np.float64]
    faces: npt.NDArray[np.int64]
    adjacency: str

Rational = Union[int, str, Any]  # int, fractions.Fraction or text such as "1000.5"

class Betti(TypedDict):
    betti: tuple[int, ...]
    euler: int
    adjacency: str

class ConvergeResult(TypedDict):
    runs: list[dict[str, Any]]
    fits: list[dict[str, Any]]
    all_pass: bool

Point = tuple[int, int]

def cf(p: int, q: int) -> ContinuedFraction: ...
def christoffel(p: int, q: int, *, upper: bool = False, word: bool = True) -> ChristoffelWord: ...
def floor_sum(n: int, m: int, a: int, b: int) -> FloorSum: ...
def sturmian(a: int, b: int, d: int, c: int, *, length: int = 64) -> Sturmian: ...
def motion_check(a: int, b: int, c: int, *,
                 center: Optional[tuple[Rational, Rational]] = None,
                 translation: Optional[tuple[Rational, Rational]] = None) -> dict[str, Any]: ...
def recognize_dss(points: Sequence[Point], connectivity: int = 0) -> DssRecognition: ...
def tangential_cover(points: Sequence[Point], closed: bool = True,
                     connectivity: int = 0) -> list[MaximalSegment]: ...
def dsl_subsegment(a: int, b: int, mu: int, x0: int, x1: int) -> DslSubsegment: ...
@overload
def hull(points: Sequence[tuple[int, int]]) -> Hull: ...
@overload
def hull(points: Sequence[tuple[int, int, int]]) -> Hull3d: ...
def convex_check(points: Sequence[Sequence[int]], definition: str = "full",
                 max_columns: int = ...) -> dict[str, Any]: ...
def hull_disc(cx: Rational, cy: Rational, r: Rational,
              max_vertices: int = 100_000_000) -> Hull: ...
def hull_ellipse(cx: Rational, cy: Rational, a: Rational, b: Rational,
                 max_vertices: int = 100_000_000) -> Hull: ...
def recognize_plane(points: Sequence[tuple[int, int, int]]) -> PlaneRecognition: ...
def probe_plane(a: int, b: int, c: int, algorithm: Literal["h", "r"] = "r",
                max_steps: int = 1_000_000) -> PlaneProbing: ...
def power_map(weights: npt.ArrayLike, *, metric: str = "l2",
              torus: Union[None, bool, Sequence[bool]] = None,
              threads: int = 0) -> tuple[npt.NDArray[np.int64], npt.NDArray[np.uint8]]: ...
def surface(volume: npt.ArrayLike, *, mesh: Literal["primal", "marching-cubes"] = "primal",
            adjacency: Optional[str] = None,
            spacing: Optional[Sequence[float]] = None,
            estimate: Optional[Literal["mean", "principal"]] = None, h: float = 1.0,
            radius: Optional[float] = None, threads: int = 0) -> dict[str, Any]: ...
def hull_halfplanes(halfplanes: Sequence[Sequence[Rational]]) -> dict[str, Any]: ...
def simple_points(image: npt.ArrayLike, *,
                  adjacency: Optional[str] = None) -> npt.NDArray[np.uint8]: ...
def contour(image: npt.ArrayLike, *, adjacency: str = "4,8", estimates: Sequence[str] = (),
            radius: str = "5v", spacing: Optional[Sequence[float]] = None,
            threads: int = 0) -> dict[str, Any]: ...
def reconstruct(points: npt.ArrayLike, normals: Optional[npt.ArrayLike] = None, *, h: float,
                method: str = "hoppe", k: int = 10, normals_k: int = 10, beta: float = 2.0,
                exact: bool = False, rbf_centers: int = 1000, rbf_offset: float = 0.0,
                imls_radius: float = 0.0, margin: int = 3,
                threads: int = 0) -> dict[str, Any]: ...
def skeleton(image: npt.ArrayLike, method: str = "critical-kernel", skeleton: str = "curve",
             adjacency: Optional[str] = None, threads: int = 0) -> npt.NDArray[np.uint8]: ...
def voronoi_map(image: npt.ArrayLike, *, metric: str = "l2",
                torus: Union[None, bool, Sequence[bool]] = None,
                threads: int = 0) -> npt.NDArray[np.int64]: ...
def reverse_distance_transform(values: npt.ArrayLike, *, metric: str = "l2",
                               torus: Union[None, bool, Sequence[bool]] = None,
                               threads: int = 0) -> npt.NDArray[np.uint8]: ...
def reduced_medial_axis(image: npt.ArrayLike, *, metric: str = "l2",
                        torus: Union[None, bool, Sequence[bool]] = None, threads: int = 0
                        ) -> tuple[npt.NDArray[np.int64], npt.NDArray[np.int64]]: ...
def chamfer_transform(image: npt.ArrayLike, *, mask: Optional[Sequence[int]] = None
                      ) -> npt.NDArray[np.uint64]: ...
def local_thickness(image: npt.ArrayLike, *, threads: int = 0) -> npt.NDArray[np.float32]: ...
def voxel_dag(volume: npt.ArrayLike, *, kind: str = "ssvdag") -> dict[str, Any]: ...
def dag_ray_hits(volume: npt.ArrayLike, origin: Sequence[int], vector: Sequence[int],
                 denominator: int = 1, *, kind: str = "ssvdag", max_hits: Optional[int] = None
                 ) -> list[tuple[tuple[int, int, int], int]]: ...
def distance_transform(image: npt.ArrayLike, *, metric: str = "l2",
                       torus: Union[None, bool, Sequence[bool]] = None,
                       threads: int = 0) -> np.ndarray: ...
def connected_components(image: npt.ArrayLike, k: int = 0, *, phase: str = "object",
                         order: str = "size", threads: int = 0
                         ) -> tuple[npt.NDArray[np.uint32], npt.NDArray[np.int64],
                                    npt.NDArray[np.bool_]]: ...
def betti_numbers(image: npt.ArrayLike, adjacency: Optional[str] = None, *,
                  threads: int = 0) -> Betti: ...
def thinning(image: npt.ArrayLike, *, method: str = "critical-kernel", skeleton: str = "ultimate",
             adjacency: Optional[str] = None, threads: int = 0) -> npt.NDArray[np.uint8]: ...
def surfels(volume: npt.ArrayLike, *, threads: int = 0) -> dict[str, np.ndarray]: ...
def ii_curvature(volume: npt.ArrayLike, *, h: float, radius: float, principal: bool = False,
                 threads: int = 0) -> dict[str, np.ndarray]: ...
@overload
def read_volume(path: StrOrBytesPath, *, metadata: Literal[False] = ...) -> np.ndarray: ...
@overload
def read_volume(path: StrOrBytesPath, *, metadata: Literal[True]) -> tuple[np.ndarray, dict[str, Any]]: ...
def write_volume(path: StrOrBytesPath, array: npt.ArrayLike, *, force: bool = False) -> None: ...
def converge(shapes: Sequence[str], estimators: Sequence[str], *,
             h: Union[str, Sequence[float]], k: Union[None, float, str] = None,
             alpha: Union[None, float, str] = None, translations: int = 0, seed: int = 0,
             fit_levels: int = 0, tolerance: float = 0.1, threads: int = 1,
             box: Optional[tuple[float, float]] = None) -> ConvergeResult: ...
def plot(result: ConvergeResult, norm: str = "linf", ax: Any = None) -> Any: ...
def mesh_html(vertices: npt.ArrayLike, faces: npt.ArrayLike,
              fields: Optional[dict[str, npt.ArrayLike]] = None,
              normals: Optional[npt.ArrayLike] = None, *, title: str = "zdg view",
              field: str = "", max_faces: int = 2_000_000) -> str: ...

class Viewer:
    faces: int
    fields: tuple[str, ...]
    title: str
    width: str
    height: str
    def __init__(self, page: str, faces: int, fields: Sequence[str], title: str) -> None: ...
    @property
    def html(self) -> str: ...
    def _repr_html_(self) -> str: ...
    def save(self, path: StrOrBytesPath, force: bool = False) -> StrOrBytesPath: ...

MeshArrays = Union[
    Mapping[str, Any],  # zdg.surface's result, or {'vertices', 'faces', 'fields', 'face_normals'}
    tuple[npt.ArrayLike, npt.ArrayLike],
    tuple[npt.ArrayLike, npt.ArrayLike, Optional[Mapping[str, npt.ArrayLike]]],
    tuple[npt.ArrayLike, npt.ArrayLike, Optional[Mapping[str, npt.ArrayLike]],
          Optional[npt.ArrayLike]],
]

def view(obj: MeshArrays, field: Optional[str] = None, title: Optional[str] = None,
         max_faces: Optional[int] = None) -> Viewer: ...
