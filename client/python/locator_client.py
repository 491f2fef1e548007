"""A small Python client of the locator.v1.Locator gRPC service.

    from locator_client import LocatorClient

    with LocatorClient("127.0.0.1:50051", deadline_s=5.0) as client:
        here = client.locate(0.5, 0.5)
        print(here.type, here.triangle_id, here.vertex_ids, here.value)
        for answer in client.locate_batch([0.1, 0.2], [0.3, 0.4], values=True):
            print(answer.triangle_id, answer.value)

    # A named dataset, queried in lon/lat; a profile; a raster.
    with LocatorClient("127.0.0.1:50051", dataset="terrain",
                       crs="EPSG:4326") as client:
        print(client.locate(15.0, 49.65).value)
        line = client.profile([(15.0, 49.64), (15.02, 49.66)], samples=50)
        for point in line.breakpoints:
            print(point.distance, point.value)
        values, header = client.grid((497000, 5497000, 503000, 5503000),
                                     cell_size=50, nodata=-9999)
        print(values.shape, header.geotransform)

    # A tile set served by shards (locatord --tiles K/N) behind a router
    # (locatord --route --shards ...): asks the router once for the
    # dataset's topology, then sends each point straight to its shard.
    with LocatorClient("router:50051", dataset="big", route=True) as client:
        print(len(client.topology().shards))
        answers = client.locate_batch(xs, ys, values=True)

Every call gets the client's deadline (a Grid stream: one deadline for the
whole stream). A failed call raises LocatorError with the gRPC status
code's name and the server's message. LocateBatch sends the points as
packed columns (xs, ys) and reads the answer's columns back into one
Location per point, in input order.

Datasets and CRSs: `dataset=` names the server's dataset ("": its default
one) and `crs=` the CRS the points are in ("EPSG:4326", WKT or a PROJ
string, x = longitude/easting; "": the dataset's own coordinates). Both
are client-wide defaults given to the constructor, and every call may give
its own (None: the client's). `interpolation=` is "linear" (the server's
default), "natural-neighbor" or "nearest".

Routing: with `route=True`, locate() and locate_batch() first ask the
target for the dataset's topology (GetTopology, once per dataset; the
client keeps it for its life) and send each point to the shard serving
its tile, as a router (locatord --route) would: a batch is split into one
LocateBatch per shard, sent concurrently, and its answers merged back into
input order (the same Locations an unrouted call returns). A dataset that
is not tiled, or served by one shard, is called on the target as without
routing. An incomplete topology (a shard started with --tiles answers for
itself alone) raises LocatorError FAILED_PRECONDITION. Points in a `crs`
are routed where PROJ puts them in the dataset's CRS (the topology's crs),
as a shard maps them: that needs pyproj (Debian: python3-pyproj), over the
same PROJ library as the server; without it they raise INVALID_ARGUMENT
(send them to a router, which maps them itself). A call with a point PROJ
cannot map, or outside the area of use of either CRS, goes whole to the
first shard, which refuses it in the server's words. An error from a shard
names it in its details.

Needs grpcio and protobuf (Debian: python3-grpcio, python3-protobuf) and the
stubs generated from proto/locator/v1/locator.proto; grid() also needs
numpy (python3-numpy), and routing points in a crs pyproj (python3-pyproj).
The build puts the stubs and a copy of this module in build/python, so
PYTHONPATH=build/python makes both importable.
"""

import bisect
import dataclasses
import json
import math
import threading
from typing import List, Optional, Sequence, Tuple

import grpc

from locator.v1 import locator_pb2, locator_pb2_grpc

__all__ = ["LocatorClient", "LocatorError", "Location", "DatasetInfo",
           "ProfilePoint", "ProfileGap", "Profile", "GridHeader"]

# Retries UNAVAILABLE only, as the C++ client's --retry does
# (client/locator_client.cc): the call never reached a live server.
_RETRY_SERVICE_CONFIG = json.dumps({
    "methodConfig": [{
        "name": [{"service": "locator.v1.Locator"}],
        "retryPolicy": {
            "maxAttempts": 5,
            "initialBackoff": "0.05s",
            "maxBackoff": "1s",
            "backoffMultiplier": 2,
            "retryableStatusCodes": ["UNAVAILABLE"],
        },
    }]
})

_TYPE_PREFIX = "LOCATION_TYPE_"
_KIND_PREFIX = "PROFILE_POINT_KIND_"

# The `interpolation=` names, as the CLI's --interpolation takes them.
_INTERPOLATIONS = {
    "linear": locator_pb2.INTERPOLATION_LINEAR,
    "natural-neighbor": locator_pb2.INTERPOLATION_NATURAL_NEIGHBOR,
    "nearest": locator_pb2.INTERPOLATION_NEAREST,
}

# HilbertKey (common/hilbert.h), by which tile sets are cut into tiles:
# a 2^16 x 2^16 grid of cells over the tile set's bounds. A tile set's
# grid is coarser, at most 2^15 x 2^15 (its cells count in a uint32).
_HILBERT_BITS = 16
_HILBERT_CELLS = 1 << _HILBERT_BITS
_MAX_GRID_LEVEL = 15


def _hilbert_walk_table() -> Tuple[int, ...]:
    """hilbert.h's kWalkTable: the Hilbert walk four levels at a time.
    From the largest quadrants down, a quadrant's bits, seen in the frame
    the quadrants above it left (x and y exchanged or not, both
    complemented or not), give two bits of the position, and the lower
    left and right quadrants turn the frame. Entry (state << 8 | 4 bits of
    x << 4 | 4 bits of y) holds the 8 position bits of those four levels
    and, above them, the state after them (swap | complement << 1)."""
    table = [0] * 1024
    for state in range(4):
        for xs in range(16):
            for ys in range(16):
                swap, complement = state & 1, state >> 1
                d = 0
                for level in range(3, -1, -1):
                    bx = ((xs >> level) & 1) ^ complement
                    by = ((ys >> level) & 1) ^ complement
                    rx, ry = (by, bx) if swap else (bx, by)
                    d = (d << 2) | ((3 * rx) ^ ry)
                    if ry == 0:
                        complement ^= rx
                        swap ^= 1
                table[state << 8 | xs << 4 | ys] = (
                    d | (swap | complement << 1) << 8)
    return tuple(table)


_WALK_TABLE = _hilbert_walk_table()


def _hilbert_index(x: int, y: int) -> int:
    """The position of cell (x, y) of the 2^16 x 2^16 grid along the
    Hilbert curve (HilbertIndex)."""
    d = state = 0
    for shift in (12, 8, 4, 0):
        step = _WALK_TABLE[state << 8 | ((x >> shift) & 15) << 4 |
                           ((y >> shift) & 15)]
        d = d << 8 | (step & 0xff)
        state = step >> 8
    return d


def _hilbert_cell(v: float, lo: float, hi: float) -> int:
    """The cell of coordinate v in a 2^16 grid over [lo, hi]
    (HilbertCell): values outside take the nearest border cell, NaN cell
    0; computed on halves where hi - lo overflows a double."""
    extent = hi - lo
    t = 0.0
    if math.isfinite(extent):
        if extent > 0:
            t = (v - lo) / extent * _HILBERT_CELLS
    else:
        t = (v * 0.5 - lo * 0.5) / (hi * 0.5 - lo * 0.5) * _HILBERT_CELLS
    if not t > 0:  # also NaN
        return 0
    return _HILBERT_CELLS - 1 if t >= _HILBERT_CELLS - 1 else int(t)


def _hilbert_key(x: float, y: float,
                 bounds: Tuple[float, float, float, float]) -> int:
    """The Hilbert position of (x, y)'s cell in the 2^16 x 2^16 grid over
    `bounds` (min_x, min_y, max_x, max_y) (HilbertKey)."""
    return _hilbert_index(_hilbert_cell(x, bounds[0], bounds[2]),
                          _hilbert_cell(y, bounds[1], bounds[3]))


class LocatorError(Exception):
    """A call that failed: `code` is the status code's name, e.g.
    "INVALID_ARGUMENT"; `details` is the server's message."""

    def __init__(self, code: str, details: str):
        super().__init__(f"{code}: {details}")
        self.code = code
        self.details = details


@dataclasses.dataclass(frozen=True)
class Location:
    """Where one query point lies in the triangulation.

    type: "FACE", "EDGE", "VERTEX", "OUTSIDE_CONVEX_HULL" or
        "OUTSIDE_DOMAIN".
    triangle_id: the triangle's stable id.
    vertex_ids: its corners' dataset indices, counter-clockwise (empty for
        a batch that did not ask for them).
    barycentric: the point's barycentric coordinates, parallel to
        vertex_ids (empty when not asked for, or outside the hull).
    value: the dataset's z interpolated at the point; None when the
        dataset has no values, the point is outside the hull, or a batch
        did not ask for values.
    cost: the server's work for this answer (the paper's metric).
    """

    type: str
    triangle_id: int
    vertex_ids: Tuple[int, ...]
    barycentric: Tuple[float, ...]
    value: Optional[float]
    cost: int


@dataclasses.dataclass(frozen=True)
class DatasetInfo:
    """One dataset a server holds.

    name: as the `dataset=` arguments take it.
    is_default: whether calls without a dataset go to it.
    serving: False while its first build is still running (stats is then
        empty).
    strategy, generation: as stats() reports them.
    stats: its locator_pb2.DatasetStats (points, triangles, bounding box,
        crs, ...).
    """

    name: str
    is_default: bool
    serving: bool
    strategy: str
    generation: int
    stats: locator_pb2.DatasetStats


@dataclasses.dataclass(frozen=True)
class ProfilePoint:
    """A point of a profile.

    kind: "LINE_VERTEX", "EDGE_CROSSING" (a breakpoint of the surface),
        "MESH_VERTEX" or "SAMPLE".
    x, y: where it is, in the dataset's CRS.
    distance: from the line's first vertex, along the line, in the
        dataset's CRS units.
    segment: the index of the line segment it lies on.
    value: the surface there; None in a gap or without values.
    triangle_id: the triangle the line runs through after it; -1 where a
        gap begins or the line ends outside.
    """

    kind: str
    x: float
    y: float
    distance: float
    segment: int
    value: Optional[float]
    triangle_id: int


@dataclasses.dataclass(frozen=True)
class ProfileGap:
    """A stretch of the line without values: from_distance to to_distance,
    because of `reason` ("OUTSIDE_CONVEX_HULL" or "OUTSIDE_DOMAIN")."""

    from_distance: float
    to_distance: float
    reason: str


@dataclasses.dataclass(frozen=True)
class Profile:
    """The surface along a polyline.

    breakpoints: the line's vertices, its edge crossings and the mesh
        vertices it passes through, in order along the line: between two
        consecutive ones with values the surface is linear along the line.
    samples: the requested evenly spaced points, in order.
    gaps: stretches outside the hull or the domain, in order.
    length: the line's length in the dataset's CRS units.
    crossings: triangle edges the line crosses.
    """

    breakpoints: Tuple[ProfilePoint, ...]
    samples: Tuple[ProfilePoint, ...]
    gaps: Tuple[ProfileGap, ...]
    length: float
    crossings: int


@dataclasses.dataclass(frozen=True)
class GridHeader:
    """A raster's shape: width x height cells over box (min_x, min_y,
    max_x, max_y), cell_width x cell_height each, row 0 at max_y (north
    up); nodata for cells without a value; crs_wkt the dataset's CRS ("":
    none)."""

    width: int
    height: int
    box: Tuple[float, float, float, float]
    cell_width: float
    cell_height: float
    nodata: float
    crs_wkt: str

    @property
    def geotransform(self) -> Tuple[float, ...]:
        """GDAL's geotransform of the raster (north up)."""
        return (self.box[0], self.cell_width, 0.0, self.box[3], 0.0,
                -self.cell_height)


def _type_name(number: int) -> str:
    return locator_pb2.LocationType.Name(number).removeprefix(_TYPE_PREFIX)


def _interpolation(name: Optional[str]) -> int:
    if name is None:
        return locator_pb2.INTERPOLATION_UNSPECIFIED
    if name not in _INTERPOLATIONS:
        raise ValueError(f"interpolation must be one of "
                         f"{', '.join(_INTERPOLATIONS)}, not {name!r}")
    return _INTERPOLATIONS[name]


def _profile_point(point) -> ProfilePoint:
    return ProfilePoint(
        kind=locator_pb2.ProfilePointKind.Name(point.kind).removeprefix(
            _KIND_PREFIX),
        x=point.point.x, y=point.point.y, distance=point.distance,
        segment=point.segment,
        value=point.value if point.HasField("value") else None,
        triangle_id=point.triangle_id)


def _broken_grid(what: str) -> LocatorError:
    return LocatorError("INTERNAL", f"the server's grid stream: {what}")


def _rpc_error(error: grpc.RpcError,
               shard: Optional[str] = None) -> LocatorError:
    """A failed call as a LocatorError; a routed call's names its shard."""
    details = error.details()
    if shard is not None:
        details = f"shard {shard}: {details}"
    return LocatorError(error.code().name, details)


def _location(answer: locator_pb2.LocateResponse) -> Location:
    return Location(
        type=_type_name(answer.type),
        triangle_id=answer.triangle_id,
        vertex_ids=tuple(answer.vertex_ids),
        barycentric=tuple(answer.barycentric),
        value=answer.value if answer.HasField("value") else None,
        cost=answer.cost.total)


def _batch_locations(answer: locator_pb2.LocateBatchResponse, count: int,
                     server: str = "the server") -> list:
    """The Location of each of the `count` points of a LocateBatch answer,
    in order; INTERNAL if `server` answered another number of points."""
    if len(answer.types) != count:
        raise LocatorError(
            "INTERNAL", f"{server} answered {len(answer.types)} of "
            f"{count} points")

    def triple(column, i):
        return tuple(column[3 * i:3 * i + 3]) if column else ()

    def value(i):
        if not answer.values or math.isnan(answer.values[i]):
            return None
        return answer.values[i]

    return [
        Location(type=_type_name(answer.types[i]),
                 triangle_id=answer.triangle_ids[i],
                 vertex_ids=triple(answer.vertex_ids, i),
                 barycentric=triple(answer.barycentric, i),
                 value=value(i),
                 cost=answer.costs[i])
        for i in range(count)
    ]


@dataclasses.dataclass(frozen=True)
class _ShardMap:
    """A tiled dataset's topology as routing uses it (the C++ clients'
    ShardMap, common/routing/shard_map.h). Tile t holds the cells
    [first_cells[t], first_cells[t + 1]) along the Hilbert curve of the
    2^grid_level x 2^grid_level grid over `bounds`; shard_of_tile[t]
    serves it, at targets[shard_of_tile[t]] ("": the client's target)."""

    dataset: str
    bounds: Tuple[float, float, float, float]
    grid_level: int
    first_cells: Tuple[int, ...]
    shard_of_tile: Tuple[int, ...]
    targets: Tuple[str, ...]
    crs: str  # the dataset's CRS ("": none)

    def tile_of(self, x: float, y: float) -> int:
        """The tile holding (x, y); every point has one (HilbertCell)."""
        cell = _hilbert_key(x, y, self.bounds) >> (
            2 * (_HILBERT_BITS - self.grid_level))
        return bisect.bisect_right(self.first_cells, cell) - 1

    def shard_of(self, x: float, y: float) -> int:
        """The index in `targets` of the shard serving (x, y)."""
        return self.shard_of_tile[self.tile_of(x, y)]

    def split(self, xs: Sequence[float], ys: Sequence[float]
              ) -> List[List[int]]:
        """positions[s]: the indices of the points (xs[i], ys[i]) shard s
        serves, ascending. LocatorError INVALID_ARGUMENT, as the server's,
        for a point with a coordinate that is not finite (a shard would
        name it by its index in its own part)."""
        positions = [[] for _ in self.targets]
        for i, (x, y) in enumerate(zip(xs, ys)):
            x, y = float(x), float(y)
            if not (math.isfinite(x) and math.isfinite(y)):
                raise LocatorError(
                    "INVALID_ARGUMENT",
                    f"point {i} has a non-finite coordinate ({x!r}, {y!r})")
            positions[self.shard_of(x, y)].append(i)
        return positions


def _shard_map(topology: locator_pb2.GetTopologyResponse
               ) -> Optional[_ShardMap]:
    """How to route the points of `topology`'s dataset: None when the
    server that answered serves them all (a dataset that is not tiled, or
    one shard). LocatorError FAILED_PRECONDITION when a tile has no shard,
    INTERNAL when the topology is malformed."""
    name = topology.dataset

    def malformed(what: str) -> LocatorError:
        return LocatorError(
            "INTERNAL", f"the server's topology of dataset '{name}': {what}")

    shard_of_tile = []
    if topology.tiled:
        level = topology.grid_level
        if level > _MAX_GRID_LEVEL:
            raise malformed(f"grid level {level} is above {_MAX_GRID_LEVEL}")
        b = topology.bounds
        bounds = (b.min_x, b.min_y, b.max_x, b.max_y)
        if not (all(map(math.isfinite, bounds)) and b.min_x <= b.max_x and
                b.min_y <= b.max_y):
            raise malformed("the bounds must be finite with min <= max")
        cells = 1 << (2 * level)
        first_cells = [tile.first_cell for tile in topology.tiles]
        if not first_cells or first_cells[0] != 0 or any(
                tile.end_cell != end or tile.end_cell <= tile.first_cell
                for tile, end in zip(topology.tiles,
                                     first_cells[1:] + [cells])):
            raise malformed(f"the tiles do not cover its {cells} cells in "
                            "order from cell 0")
        shard_of_tile = [None] * len(first_cells)
        for s, shard in enumerate(topology.shards):
            for tile in shard.tiles:
                if tile >= len(shard_of_tile):
                    raise malformed(f"shard {s} lists tile {tile}, which "
                                    "does not exist")
                if shard_of_tile[tile] is not None:
                    raise malformed(f"shard {s} lists tile {tile}, which "
                                    f"shard {shard_of_tile[tile]} lists")
                shard_of_tile[tile] = s
    missing = (shard_of_tile.index(None) if None in shard_of_tile
               else None)
    if not topology.complete or missing is not None:
        hole = "" if missing is None else f": tile {missing} has no shard"
        raise LocatorError(
            "FAILED_PRECONDITION",
            f"topology of dataset '{name}' is incomplete{hole}; route "
            "through a router (locatord --route)")
    if not topology.tiled or len(topology.shards) == 1:
        return None
    return _ShardMap(dataset=name, bounds=bounds, grid_level=level,
                     first_cells=tuple(first_cells),
                     shard_of_tile=tuple(shard_of_tile),
                     targets=tuple(shard.target for shard in topology.shards),
                     crs=topology.crs)


def _merge_batch(parts: Sequence[Tuple[Sequence[int], Sequence[Location]]],
                 count: int) -> list:
    """The Locations of a batch of `count` points from the answers to its
    parts: (positions, locations) pairs, locations[j] the answer for the
    batch's point positions[j]."""
    merged = [None] * count
    for positions, locations in parts:
        for i, location in zip(positions, locations):
            merged[i] = location
    return merged


class _CrsMapper:
    """Maps points from a request's CRS to a dataset's as a shard does
    (common/gis/crs_transformer.h): with PROJ, in traditional GIS axis
    order (x = longitude/easting) on both sides, a point outside the area
    of use of either CRS refused. Raises (pyproj's errors, ValueError) when
    PROJ cannot make the transformation."""

    def __init__(self, request_crs: str, dataset_crs: str):
        from pyproj import CRS, Transformer  # ImportError: no pyproj
        source = CRS.from_user_input(request_crs)
        target = CRS.from_user_input(dataset_crs)
        lon_lat = source.geodetic_crs
        if lon_lat is None or not lon_lat.is_geographic:
            raise ValueError(f"CRS {request_crs!r} has no geographic base CRS")
        self._to_dataset = Transformer.from_crs(source, target,
                                                always_xy=True)
        self._to_lon_lat = Transformer.from_crs(source, lon_lat,
                                                always_xy=True)
        self._areas = [area for area in (source.area_of_use,
                                         target.area_of_use) if area]

    def _inside(self, lon: float, lat: float) -> bool:
        """Whether (lon, lat) is in the area of use of both CRSs."""
        def contains(area) -> bool:
            if not area.south <= lat <= area.north:
                return False
            if area.west <= area.east:
                return area.west <= lon <= area.east
            return lon >= area.west or lon <= area.east  # across 180 degrees

        return all(map(contains, self._areas))

    def to_dataset(self, xs: Sequence[float], ys: Sequence[float]
                   ) -> Optional[Tuple[List[float], List[float]]]:
        """The points in the dataset's CRS (non-finite ones as they are);
        None when one cannot be mapped."""
        xs, ys = [float(x) for x in xs], [float(y) for y in ys]
        lons, lats = self._to_lon_lat.transform(xs, ys, errcheck=False)
        mapped_xs, mapped_ys = self._to_dataset.transform(xs, ys,
                                                          errcheck=False)
        mapped_xs, mapped_ys = list(mapped_xs), list(mapped_ys)
        for i, point in enumerate(zip(xs, ys)):
            if not all(map(math.isfinite, point)):
                mapped_xs[i], mapped_ys[i] = point  # split() names it
            elif not (math.isfinite(lons[i]) and math.isfinite(lats[i]) and
                      self._inside(lons[i], lats[i]) and
                      math.isfinite(mapped_xs[i]) and
                      math.isfinite(mapped_ys[i])):
                return None
        return mapped_xs, mapped_ys


class LocatorClient:
    """A channel to one locator server and the calls on it (with
    `route=True`, also a channel to each shard it routes to).

    Thread-safe: gRPC channels and stubs may be shared between threads.
    Close it (or use it as a context manager) to release the channels.
    """

    def __init__(self, target: str, deadline_s: float = 5.0,
                 retry_unavailable: bool = False,
                 max_message_bytes: int = 64 << 20,
                 dataset: str = "", crs: str = "", route: bool = False):
        """Opens a plaintext channel to `target` ("HOST:PORT"); every call
        gets `deadline_s` seconds. `retry_unavailable` adds a gRPC retry
        policy for UNAVAILABLE (a restarting server or a proxy's 502).
        `dataset` and `crs` are the defaults of every call. `route` sends
        locate() and locate_batch() to the shards serving the points, by
        the dataset's topology (the module's docstring: Routing); shard
        channels get the same options."""
        options = [("grpc.max_send_message_length", max_message_bytes),
                   ("grpc.max_receive_message_length", max_message_bytes)]
        if retry_unavailable:
            options += [("grpc.enable_retries", 1),
                        ("grpc.service_config", _RETRY_SERVICE_CONFIG)]
        self._target = target
        self._options = options
        self._channel = grpc.insecure_channel(target, options=options)
        self._stub = locator_pb2_grpc.LocatorStub(self._channel)
        self._deadline_s = deadline_s
        self._dataset = dataset
        self._crs = crs
        self._route = route
        self._topologies = {}  # dataset field -> GetTopologyResponse
        self._shard_maps = {}  # dataset field -> Optional[_ShardMap]
        # (request crs, dataset crs) -> Optional[_CrsMapper] (None: PROJ
        # cannot map between them)
        self._mappers = {}
        self._shards_lock = threading.Lock()
        self._shard_channels = {}  # target -> (channel, stub)

    def close(self):
        """Closes the channels; calls after this fail."""
        self._channel.close()
        with self._shards_lock:
            for channel, _ in self._shard_channels.values():
                channel.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc_info):
        self.close()

    def _call(self, method, request, shard: Optional[str] = None):
        """Calls `method`; a failure raises LocatorError, naming `shard`
        when the call was routed there."""
        try:
            return method(request, timeout=self._deadline_s)
        except grpc.RpcError as error:
            raise _rpc_error(error, shard) from None

    def _shard_stub(self, target: str) -> locator_pb2_grpc.LocatorStub:
        """The stub of the shard at `target` ("": this client's target),
        its channel opened on first use."""
        if not target or target == self._target:
            return self._stub
        with self._shards_lock:
            if target not in self._shard_channels:
                channel = grpc.insecure_channel(target, options=self._options)
                self._shard_channels[target] = (
                    channel, locator_pb2_grpc.LocatorStub(channel))
            return self._shard_channels[target][1]

    def _routing(self, dataset: str) -> Optional[_ShardMap]:
        """The shards to route a call on `dataset` to; None: call the
        target (no routing, or the dataset needs none)."""
        if not self._route:
            return None
        if dataset not in self._shard_maps:
            self._shard_maps[dataset] = _shard_map(self.topology(dataset))
        return self._shard_maps[dataset]

    def _routed_points(self, shard_map: _ShardMap, crs: str,
                       xs: Sequence[float], ys: Sequence[float]
                       ) -> Optional[Tuple[Sequence[float], Sequence[float]]]:
        """The points where routing reads them, in the dataset's
        coordinates: as they are without a crs; None when one cannot be
        mapped. LocatorError INVALID_ARGUMENT without pyproj."""
        if not crs:
            return xs, ys
        key = (crs, shard_map.crs)
        if key not in self._mappers:
            try:
                self._mappers[key] = _CrsMapper(*key)
            except ImportError:
                raise LocatorError(
                    "INVALID_ARGUMENT",
                    f"points in crs {crs!r} are routed to the shards of "
                    f"dataset '{shard_map.dataset}' where PROJ maps them, "
                    "which needs pyproj (Debian: python3-pyproj): install "
                    "it, or send them to a router (locatord --route)"
                ) from None
            except Exception:  # pylint: disable=broad-except
                self._mappers[key] = None  # the first shard says why
        mapper = self._mappers[key]
        return None if mapper is None else mapper.to_dataset(xs, ys)

    def _dataset_of(self, dataset: Optional[str]) -> str:
        """The dataset field of a request: the call's, else the client's."""
        return self._dataset if dataset is None else dataset

    def _scope(self, dataset: Optional[str], crs: Optional[str]) -> dict:
        """The dataset and crs fields of a request: the call's, else the
        client's."""
        return {"dataset": self._dataset_of(dataset),
                "crs": self._crs if crs is None else crs}

    def locate(self, x: float, y: float, dataset: Optional[str] = None,
               crs: Optional[str] = None,
               interpolation: Optional[str] = None) -> Location:
        """Locates the point (x, y) (routed: at the shard serving it)."""
        scope = self._scope(dataset, crs)
        request = locator_pb2.LocateRequest(
            point=locator_pb2.Point(x=x, y=y),
            interpolation=_interpolation(interpolation), **scope)
        shard_map = self._routing(scope["dataset"])
        if shard_map is None:
            return _location(self._call(self._stub.Locate, request))
        where = self._routed_points(shard_map, scope["crs"], [x], [y])
        shard = 0 if where is None else shard_map.shard_of(
            float(where[0][0]), float(where[1][0]))
        target = shard_map.targets[shard]
        return _location(self._call(self._shard_stub(target).Locate,
                                    request, shard=target or self._target))

    def locate_batch(self, xs: Sequence[float], ys: Sequence[float],
                     vertex_ids: bool = False, barycentric: bool = False,
                     values: bool = False, dataset: Optional[str] = None,
                     crs: Optional[str] = None,
                     interpolation: Optional[str] = None) -> list:
        """Locates the points (xs[i], ys[i]) in one LocateBatch call
        (routed: one per shard with points, sent concurrently) and
        returns a Location per point, in input order. The flags ask the
        server for the optional columns. ValueError if xs and ys differ in
        length; LocatorError (INVALID_ARGUMENT) if a coordinate is not
        finite."""
        if len(xs) != len(ys):
            raise ValueError(
                f"xs has {len(xs)} points but ys has {len(ys)}")
        scope = self._scope(dataset, crs)
        request = locator_pb2.LocateBatchRequest(
            include_vertex_ids=vertex_ids, include_barycentric=barycentric,
            include_values=values,
            interpolation=_interpolation(interpolation), **scope)
        shard_map = self._routing(scope["dataset"])
        where = None if shard_map is None else self._routed_points(
            shard_map, scope["crs"], xs, ys)
        if where is None:
            # Unrouted, or to the first shard, which refuses what cannot
            # be mapped.
            target = "" if shard_map is None else shard_map.targets[0]
            request.xs.extend(xs)
            request.ys.extend(ys)
            return _batch_locations(
                self._call(self._shard_stub(target).LocateBatch, request,
                           shard=shard_map and (target or self._target)),
                len(xs))
        return self._routed_batch(request, xs, ys, where, shard_map)

    def _routed_batch(self, request: locator_pb2.LocateBatchRequest,
                      xs: Sequence[float], ys: Sequence[float],
                      where: Tuple[Sequence[float], Sequence[float]],
                      shard_map: _ShardMap) -> list:
        """Locates the points at their shards, by `where` (the points in
        the dataset's coordinates): one LocateBatch with the fields of
        `request` (which has no points) per shard with points, all sent
        before any answer is awaited; the answers merged into input
        order."""
        calls = []  # (positions, shard, future)
        try:
            for target, positions in zip(shard_map.targets,
                                         shard_map.split(*where)):
                if not positions:
                    continue
                part = locator_pb2.LocateBatchRequest()
                part.CopyFrom(request)
                part.xs.extend(xs[i] for i in positions)
                part.ys.extend(ys[i] for i in positions)
                future = self._shard_stub(target).LocateBatch.future(
                    part, timeout=self._deadline_s)
                calls.append((positions, target or self._target, future))
            answers = []
            for positions, shard, future in calls:
                try:
                    answer = future.result()
                except grpc.RpcError as error:
                    raise _rpc_error(error, shard) from None
                answers.append((positions, _batch_locations(
                    answer, len(positions), f"shard {shard}")))
        finally:
            for _, _, future in calls:
                future.cancel()  # a no-op once the call has ended
        return _merge_batch(answers, len(xs))

    def topology(self, dataset: Optional[str] = None
                 ) -> locator_pb2.GetTopologyResponse:
        """The dataset's topology: its tiles and the shards serving them
        (GetTopology). Fetched once per dataset, then kept for the
        client's life."""
        name = self._dataset_of(dataset)
        if name not in self._topologies:
            topology = self._call(self._stub.GetTopology,
                                  locator_pb2.GetTopologyRequest(dataset=name))
            self._topologies.setdefault(name, topology)
        return self._topologies[name]

    def stats(self, dataset: Optional[str] = None
              ) -> locator_pb2.GetStatsResponse:
        """The dataset's, serving and tuning statistics. For a raster DEM
        or a dataset served with max_error, dataset.simplification is the
        certificate: source_samples, vertices, triangles, the max_error
        measured over every source sample, target_error, max_points and
        build_seconds (HasField("simplification") is False otherwise)."""
        request = locator_pb2.GetStatsRequest(
            dataset=self._dataset_of(dataset))
        return self._call(self._stub.GetStats, request)

    def list_datasets(self) -> list:
        """The server's datasets, as DatasetInfo, in the server's order
        (stats is the DatasetStats of stats(), simplification included)."""
        answer = self._call(self._stub.ListDatasets,
                            locator_pb2.ListDatasetsRequest())
        return [DatasetInfo(name=entry.name, is_default=entry.is_default,
                            serving=entry.serving, strategy=entry.strategy,
                            generation=entry.generation, stats=entry.stats)
                for entry in answer.datasets]

    def profile(self, vertices: Sequence[Tuple[float, float]],
                samples: int = 0, dataset: Optional[str] = None,
                crs: Optional[str] = None,
                interpolation: Optional[str] = None) -> Profile:
        """The surface along the polyline `vertices` ((x, y) pairs, at
        least 2), with `samples` evenly spaced points too. LocatorError
        RESOURCE_EXHAUSTED when the line crosses more triangle edges than
        the server allows."""
        request = locator_pb2.ProfileRequest(
            vertices=[locator_pb2.Point(x=x, y=y) for x, y in vertices],
            samples=samples, interpolation=_interpolation(interpolation),
            **self._scope(dataset, crs))
        answer = self._call(self._stub.Profile, request)
        return Profile(
            breakpoints=tuple(map(_profile_point, answer.breakpoints)),
            samples=tuple(map(_profile_point, answer.samples)),
            gaps=tuple(ProfileGap(from_distance=gap.from_distance,
                                  to_distance=gap.to_distance,
                                  reason=_type_name(gap.reason))
                       for gap in answer.gaps),
            length=answer.length, crossings=answer.crossings)

    def grid(self, box: Tuple[float, float, float, float],
             width: Optional[int] = None, height: Optional[int] = None,
             cell_size: Optional[float] = None,
             interpolation: Optional[str] = None,
             nodata: Optional[float] = None, dataset: Optional[str] = None):
        """Renders the surface over `box` (min_x, min_y, max_x, max_y, in
        the dataset's CRS) to width x height cells, or to square cells of
        `cell_size` (the box then grows east and south to whole cells).
        Returns (values, header): a numpy float64 array of header.height
        rows (row 0 the northern edge) by header.width columns, cells
        without a value holding `nodata` (default NaN), and the GridHeader.
        ValueError unless the size is given one way; LocatorError
        RESOURCE_EXHAUSTED above the server's cell limit, and INTERNAL for
        a stream that breaks the contract."""
        import numpy  # only grid() needs it

        if (cell_size is None) == (width is None or height is None):
            raise ValueError("give width and height, or cell_size")
        request = locator_pb2.GridRequest(
            box=locator_pb2.BoundingBox(min_x=box[0], min_y=box[1],
                                        max_x=box[2], max_y=box[3]),
            width=width or 0, height=height or 0, cell_size=cell_size or 0,
            interpolation=_interpolation(interpolation),
            dataset=self._dataset_of(dataset))
        if nodata is not None:
            request.nodata = nodata
        values = header = received = None
        stream = self._stub.Grid(request, timeout=self._deadline_s)
        try:
            for message in stream:
                if message.HasField("header") != (header is None):
                    raise _broken_grid("the header must come first, once")
                if header is None:
                    header = self._grid_header(message.header)
                    values = numpy.full((header.height, header.width),
                                        header.nodata, dtype=numpy.float64)
                    received = numpy.zeros(header.height, dtype=bool)
                first, rows = message.first_row, message.rows
                if first + rows > header.height:
                    raise _broken_grid(f"rows {first} + {rows} outside the "
                                       f"raster's {header.height}")
                if len(message.values) != rows * header.width:
                    raise _broken_grid(f"{len(message.values)} values for "
                                       f"{rows} rows of {header.width}")
                if received[first:first + rows].any():
                    raise _broken_grid("a row twice")
                received[first:first + rows] = True
                values[first:first + rows] = numpy.asarray(
                    message.values, dtype=numpy.float64).reshape(
                        rows, header.width)
        except grpc.RpcError as error:
            raise _rpc_error(error) from None
        finally:
            stream.cancel()  # a no-op once the stream has ended
        if header is None:
            raise _broken_grid("no header")
        if not received.all():
            raise _broken_grid(f"ended after {int(received.sum())} of "
                               f"{header.height} rows")
        return values, header

    @staticmethod
    def _grid_header(header) -> GridHeader:
        if header.width == 0 or header.height == 0:
            raise _broken_grid(f"the header's raster is {header.width} x "
                               f"{header.height}")
        return GridHeader(
            width=header.width, height=header.height,
            box=(header.box.min_x, header.box.min_y, header.box.max_x,
                 header.box.max_y),
            cell_width=header.cell_width, cell_height=header.cell_height,
            nodata=header.nodata, crs_wkt=header.crs_wkt)
