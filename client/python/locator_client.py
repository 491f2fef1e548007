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

Needs grpcio and protobuf (Debian: python3-grpcio, python3-protobuf) and the
stubs generated from proto/locator/v1/locator.proto; grid() also needs
numpy (python3-numpy). The build puts the stubs and a copy of this module
in build/python, so PYTHONPATH=build/python makes both importable.
"""

import dataclasses
import json
import math
from typing import Optional, Sequence, Tuple

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


class LocatorClient:
    """A channel to one locator server and the calls on it.

    Thread-safe: gRPC channels and stubs may be shared between threads.
    Close it (or use it as a context manager) to release the channel.
    """

    def __init__(self, target: str, deadline_s: float = 5.0,
                 retry_unavailable: bool = False,
                 max_message_bytes: int = 64 << 20,
                 dataset: str = "", crs: str = ""):
        """Opens a plaintext channel to `target` ("HOST:PORT"); every call
        gets `deadline_s` seconds. `retry_unavailable` adds a gRPC retry
        policy for UNAVAILABLE (a restarting server or a proxy's 502).
        `dataset` and `crs` are the defaults of every call."""
        options = [("grpc.max_send_message_length", max_message_bytes),
                   ("grpc.max_receive_message_length", max_message_bytes)]
        if retry_unavailable:
            options += [("grpc.enable_retries", 1),
                        ("grpc.service_config", _RETRY_SERVICE_CONFIG)]
        self._channel = grpc.insecure_channel(target, options=options)
        self._stub = locator_pb2_grpc.LocatorStub(self._channel)
        self._deadline_s = deadline_s
        self._dataset = dataset
        self._crs = crs

    def close(self):
        """Closes the channel; calls after this fail."""
        self._channel.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc_info):
        self.close()

    def _call(self, method, request):
        try:
            return method(request, timeout=self._deadline_s)
        except grpc.RpcError as error:
            raise LocatorError(error.code().name, error.details()) from None

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
        """Locates the point (x, y)."""
        request = locator_pb2.LocateRequest(
            point=locator_pb2.Point(x=x, y=y),
            interpolation=_interpolation(interpolation),
            **self._scope(dataset, crs))
        answer = self._call(self._stub.Locate, request)
        return Location(
            type=_type_name(answer.type),
            triangle_id=answer.triangle_id,
            vertex_ids=tuple(answer.vertex_ids),
            barycentric=tuple(answer.barycentric),
            value=answer.value if answer.HasField("value") else None,
            cost=answer.cost.total)

    def locate_batch(self, xs: Sequence[float], ys: Sequence[float],
                     vertex_ids: bool = False, barycentric: bool = False,
                     values: bool = False, dataset: Optional[str] = None,
                     crs: Optional[str] = None,
                     interpolation: Optional[str] = None) -> list:
        """Locates the points (xs[i], ys[i]) in one LocateBatch call and
        returns a Location per point, in input order. The flags ask the
        server for the optional columns. ValueError if xs and ys differ in
        length; LocatorError (INVALID_ARGUMENT) if a coordinate is not
        finite."""
        if len(xs) != len(ys):
            raise ValueError(
                f"xs has {len(xs)} points but ys has {len(ys)}")
        request = locator_pb2.LocateBatchRequest(
            xs=xs, ys=ys, include_vertex_ids=vertex_ids,
            include_barycentric=barycentric, include_values=values,
            interpolation=_interpolation(interpolation),
            **self._scope(dataset, crs))
        answer = self._call(self._stub.LocateBatch, request)
        if len(answer.types) != len(xs):
            raise LocatorError(
                "INTERNAL", f"the server answered {len(answer.types)} of "
                f"{len(xs)} points")

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
            for i in range(len(xs))
        ]

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
            raise LocatorError(error.code().name, error.details()) from None
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
