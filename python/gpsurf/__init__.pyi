# Type stubs of the package gpsurf (its extension module _gpsurf); tests/python/test_stubs.py checks
# them against the module's own signatures.
import os
from typing import Any, Callable, Literal, Optional, Sequence, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

__version__: str

PathLike = Union[str, bytes, os.PathLike[str], os.PathLike[bytes]]
FloatArray = npt.NDArray[np.float64]
IntArray = npt.NDArray[np.int32]
Progress = Optional[Callable[[float], Optional[bool]]]

class Error(RuntimeError): ...
class Cancelled(Error): ...

class Mesh:
    def __init__(
        self, positions: npt.ArrayLike, faces: Union[npt.ArrayLike, Sequence[Sequence[int]]], covariances: Optional[npt.ArrayLike] = None
    ) -> None: ...
    @property
    def n_vertices(self) -> int: ...
    @property
    def n_faces(self) -> int: ...
    @property
    def positions(self) -> FloatArray: ...
    @positions.setter
    def positions(self, value: npt.ArrayLike) -> None: ...
    @property
    def covariances(self) -> FloatArray: ...
    @covariances.setter
    def covariances(self, value: npt.ArrayLike) -> None: ...
    @property
    def faces(self) -> IntArray: ...
    @property
    def face_offsets(self) -> IntArray: ...
    @property
    def face_indices(self) -> IntArray: ...
    @property
    def creases(self) -> Tuple[Tuple[int, int, float], ...]: ...
    @creases.setter
    def creases(self, value: Sequence[Tuple[int, int, float]]) -> None: ...
    @property
    def crease_edges(self) -> IntArray: ...
    @property
    def crease_sharpness(self) -> FloatArray: ...
    @property
    def corners(self) -> FloatArray: ...
    @corners.setter
    def corners(self, value: npt.ArrayLike) -> None: ...
    def write(self, path: PathLike, binary: bool = False) -> None: ...
    def copy(self) -> Mesh: ...
    def __copy__(self) -> Mesh: ...
    def __deepcopy__(self, memo: Any) -> Mesh: ...

class Surface:
    def __init__(
        self, mesh: Mesh, scheme: str = "auto", loop_beta: str = "loop", depth: int = -1, approximate: bool = False
    ) -> None: ...
    @property
    def scheme(self) -> str: ...
    @property
    def n_patches(self) -> int: ...
    @property
    def patch_corners(self) -> int: ...
    @property
    def patch_faces(self) -> IntArray: ...
    @property
    def mesh(self) -> Mesh: ...
    def evaluate(
        self, patches: npt.ArrayLike, u: npt.ArrayLike, v: npt.ArrayLike, covariances: bool = False
    ) -> Tuple[FloatArray, ...]: ...
    def update(self, mesh: Mesh, changed: Optional[npt.ArrayLike] = None, replan: bool = False) -> None: ...
    def tessellate(self, level: int = 8) -> Tuple[FloatArray, FloatArray, IntArray]: ...
    def render(
        self,
        width: int = 800,
        height: int = 600,
        level: int = 0,
        pixels: float = 0.0,
        matcap: PathLike = "clay",
        mode: str = "matcap",
        camera: Optional[Sequence[float]] = None,
        mesh_lines: bool = False,
        wireframe: bool = False,
        ellipsoids: bool = False,
        sigma: float = 1.0,
        background: Sequence[float] = ...,
        context: str = "auto",
        scalars: Optional[npt.ArrayLike] = None,
        colormap: str = "viridis",
        scalar_range: Optional[Sequence[float]] = None,
    ) -> npt.NDArray[np.float32]: ...

def read(
    path: PathLike, covariance: str = "infer", bias: float = 0.05, isotropic: float = 0.5, repair: bool = False
) -> Mesh: ...
def edit(mesh: Mesh, ops: Union[str, Sequence[dict]]) -> Mesh: ...
def simplify(
    mesh: Mesh,
    vertices: Optional[int] = None,
    bias: float = 0.05,
    progress: Progress = None,
    *,
    error: Optional[float] = None,
    quads: bool = False,
    limit: bool = False,
) -> Mesh: ...
def samples() -> list[str]: ...
def sample_description(name: str) -> str: ...
def sample(name: str, size: int = 0) -> Mesh: ...
def infer(mesh: Mesh, bias: float = 0.05) -> Mesh: ...
def subdivide(
    mesh: Mesh, levels: int = 1, limit: bool = True, scheme: str = "auto", loop_beta: str = "loop"
) -> Mesh: ...
def tessellate(
    mesh: Mesh,
    level: int = 8,
    scheme: str = "auto",
    loop_beta: str = "loop",
    depth: int = -1,
    approximate: bool = False,
) -> Tuple[FloatArray, FloatArray, IntArray]: ...
@overload
def fit(
    coarse: Mesh,
    target: Union[Mesh, npt.ArrayLike],
    iterations: int = 100,
    plain: bool = False,
    smoothness: float = 1e-05,
    tolerance: float = 0.01,
    time: Optional[float] = None,
    progress: Progress = None,
    *,
    report: Literal[True],
    covariance_smoothness: Optional[float] = None,
    covariance_prior: float = 0.0,
    min_sigma: float = 0.35,
    max_sigma: float = 1.0,
    normal_weight: float = 0.001,
    relaxed_min_sigma: float = 0.1,
) -> Tuple[Mesh, dict[str, Any]]: ...
@overload
def fit(
    coarse: Mesh,
    target: Union[Mesh, npt.ArrayLike],
    iterations: int = 100,
    plain: bool = False,
    smoothness: float = 1e-05,
    tolerance: float = 0.01,
    time: Optional[float] = None,
    progress: Progress = None,
    report: Literal[False] = False,
    *,
    covariance_smoothness: Optional[float] = None,
    covariance_prior: float = 0.0,
    min_sigma: float = 0.35,
    max_sigma: float = 1.0,
    normal_weight: float = 0.001,
    relaxed_min_sigma: float = 0.1,
) -> Mesh: ...
def distance(
    points: Union[Mesh, npt.ArrayLike], to: Union[Mesh, Surface], level: Optional[int] = None, linear: bool = False
) -> FloatArray: ...
def compare(
    a: Union[Mesh, npt.ArrayLike], b: Union[Mesh, Surface], level: Optional[int] = None, linear: bool = False
) -> dict[str, float]: ...
def render(
    mesh: Mesh,
    width: int = 800,
    height: int = 600,
    level: int = 0,
    pixels: float = 0.0,
    matcap: PathLike = "clay",
    mode: str = "matcap",
    camera: Optional[Sequence[float]] = None,
    mesh_lines: bool = False,
    wireframe: bool = False,
    ellipsoids: bool = False,
    sigma: float = 1.0,
    background: Sequence[float] = ...,
    scheme: str = "auto",
    loop_beta: str = "loop",
    context: str = "auto",
    scalars: Optional[npt.ArrayLike] = None,
    colormap: str = "viridis",
    scalar_range: Optional[Sequence[float]] = None,
) -> npt.NDArray[np.float32]: ...
def read_image(path: PathLike) -> npt.NDArray[np.float32]: ...
def write_image(path: PathLike, image: npt.ArrayLike) -> None: ...
