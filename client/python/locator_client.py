"""A small Python client of the locator.v1.Locator gRPC service.

    from locator_client import LocatorClient

    with LocatorClient("127.0.0.1:50051", deadline_s=5.0) as client:
        here = client.locate(0.5, 0.5)
        print(here.type, here.triangle_id, here.vertex_ids, here.value)
        for answer in client.locate_batch([0.1, 0.2], [0.3, 0.4], values=True):
            print(answer.triangle_id, answer.value)

Every call gets the client's deadline. A failed call raises LocatorError
with the gRPC status code's name and the server's message. LocateBatch
sends the points as packed columns (xs, ys) and reads the answer's
columns back into one Location per point, in input order.

Needs grpcio and protobuf (Debian: python3-grpcio, python3-protobuf) and the
stubs generated from proto/locator/v1/locator.proto. The build puts the
stubs and a copy of this module in build/python, so
PYTHONPATH=build/python makes both importable.
"""

import dataclasses
import json
import math
from typing import Optional, Sequence, Tuple

import grpc

from locator.v1 import locator_pb2, locator_pb2_grpc

__all__ = ["LocatorClient", "LocatorError", "Location"]

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

    type: "FACE", "EDGE", "VERTEX" or "OUTSIDE_CONVEX_HULL".
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


def _type_name(number: int) -> str:
    return locator_pb2.LocationType.Name(number).removeprefix(_TYPE_PREFIX)


class LocatorClient:
    """A channel to one locator server and the calls on it.

    Thread-safe: gRPC channels and stubs may be shared between threads.
    Close it (or use it as a context manager) to release the channel.
    """

    def __init__(self, target: str, deadline_s: float = 5.0,
                 retry_unavailable: bool = False,
                 max_message_bytes: int = 64 << 20):
        """Opens a plaintext channel to `target` ("HOST:PORT"); every call
        gets `deadline_s` seconds. `retry_unavailable` adds a gRPC retry
        policy for UNAVAILABLE (a restarting server or a proxy's 502)."""
        options = [("grpc.max_send_message_length", max_message_bytes),
                   ("grpc.max_receive_message_length", max_message_bytes)]
        if retry_unavailable:
            options += [("grpc.enable_retries", 1),
                        ("grpc.service_config", _RETRY_SERVICE_CONFIG)]
        self._channel = grpc.insecure_channel(target, options=options)
        self._stub = locator_pb2_grpc.LocatorStub(self._channel)
        self._deadline_s = deadline_s

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

    def locate(self, x: float, y: float) -> Location:
        """Locates the point (x, y)."""
        request = locator_pb2.LocateRequest(
            point=locator_pb2.Point(x=x, y=y))
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
                     values: bool = False) -> list:
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
            include_barycentric=barycentric, include_values=values)
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

    def stats(self) -> locator_pb2.GetStatsResponse:
        """The server's dataset, serving and tuning statistics."""
        return self._call(self._stub.GetStats, locator_pb2.GetStatsRequest())
