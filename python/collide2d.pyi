"""Type stubs of the `collide2d` module (python/collide2d_module.cpp; docs/python.md)."""
from typing import Optional, Sequence, Tuple

import numpy as np
import numpy.typing as npt

Point = Tuple[float, float]
PointLike = Sequence[float]

__version__: str

class UnsupportedPair(ValueError): ...

class Circle:
    def __init__(self, center: PointLike, radius: float) -> None: ...
    @property
    def center(self) -> Point: ...
    @property
    def radius(self) -> float: ...

class Ellipse:
    def __init__(self, center: PointLike, a: float, b: float, angle: float = 0.0) -> None: ...
    @property
    def center(self) -> Point: ...
    @property
    def a(self) -> float: ...
    @property
    def b(self) -> float: ...
    @property
    def angle(self) -> float: ...

class Rect:
    def __init__(self, center: PointLike, half_extents: PointLike, angle: float = 0.0) -> None: ...
    @property
    def center(self) -> Point: ...
    @property
    def half_extents(self) -> Point: ...
    @property
    def angle(self) -> float: ...

class Capsule:
    def __init__(self, center: PointLike, half_length: float, radius: float, angle: float = 0.0) -> None: ...
    @property
    def center(self) -> Point: ...
    @property
    def half_length(self) -> float: ...
    @property
    def radius(self) -> float: ...
    @property
    def angle(self) -> float: ...

class Segment:
    def __init__(self, point1: PointLike, point2: PointLike) -> None: ...
    @property
    def point1(self) -> Point: ...
    @property
    def point2(self) -> Point: ...

class ConvexPolygon:
    def __init__(self, vertices: Sequence[PointLike], radius: float = 0.0, center: PointLike = (0.0, 0.0),
                 angle: float = 0.0) -> None: ...
    @property
    def center(self) -> Point: ...
    @property
    def angle(self) -> float: ...
    @property
    def radius(self) -> float: ...
    @property
    def vertices(self) -> list[Point]: ...

Shape = Circle | Ellipse | Rect | Capsule | ConvexPolygon | Segment

class DistanceResult:
    overlapping: bool
    distance: float
    point_a: Point
    point_b: Point

class ContactPoint:
    point_a: Point
    point_b: Point
    separation: float
    id: int

class Contact:
    separation: float
    normal: Point
    point_a: Point
    point_b: Point
    manifold: list[ContactPoint]
    empty: bool

class TimeOfImpact:
    status: str
    t: float
    normal: Point
    point: Point
    iterations: int

class RayHit:
    distance: float
    point: Point
    normal: Point

def overlaps(a: Shape, b: Shape) -> bool: ...
def distance(a: Shape, b: Shape) -> DistanceResult: ...
def boundary_distance(a: Shape, b: Shape) -> DistanceResult: ...
def contact(a: Shape, b: Shape, max_separation: float = ..., margin: float = 0.0) -> Contact: ...
def time_of_impact(a: Shape, b: Shape, a_velocity: PointLike = (0.0, 0.0), a_turn: float = 0.0,
                   b_velocity: PointLike = (0.0, 0.0), b_turn: float = 0.0) -> TimeOfImpact: ...
def ray_cast(shape: Shape, origin: PointLike, direction: PointLike, max_distance: float = ...) -> Optional[RayHit]: ...

# Shapes of one kind a row, (n, k) float64: circle (cx cy r), ellipse (cx cy a b theta), rect (cx cy
# hx hy theta), capsule (cx cy half_length radius theta); row i of a with row i of b.
def overlaps_arrays(a_kind: str, a: npt.ArrayLike, b_kind: str, b: npt.ArrayLike) -> npt.NDArray[np.bool_]: ...
def distance_arrays(a_kind: str, a: npt.ArrayLike, b_kind: str, b: npt.ArrayLike) -> dict[str, np.ndarray]: ...
def contact_arrays(a_kind: str, a: npt.ArrayLike, b_kind: str, b: npt.ArrayLike) -> dict[str, np.ndarray]: ...
