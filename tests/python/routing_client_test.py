#!/usr/bin/env python3
"""ctest: the Python client's routing (LocatorClient(route=True)) without
a locatord.

The port of HilbertKey (common/hilbert.h) against positions known from
the curve's definition and against values the C++ header computed; the
topology's checks, the split of a batch over three shards and the merge
of their answers; then the client against three fake shards in this
process, whose answers are computed from the points, so that a routed
batch must return exactly what one server serving every point returns.

Usage: routing_client_test.py PYTHON_DIR
(PYTHON_DIR holds the generated stubs and locator_client.py.)
"""

import math
import sys
import threading
import unittest
from concurrent import futures

PYTHON_DIR = None  # set in main()

UNIT = (0.0, 0.0, 1.0, 1.0)
# The tile-set box of the fakes: 10 x 10.
BOUNDS = (0.0, 0.0, 10.0, 10.0)


def three_shard_topology(targets, dataset="big", complete=True,
                         shard_tiles=([0], [1], [2])):
    """A topology of a grid of level 1 over BOUNDS, cut into 3 tiles: the
    curve's 4 cells are the lower left quadrant (cell 0), the upper left
    (1), the upper right (2) and the lower right (3), so tile 0 (cell 0)
    is the lower left quadrant, tile 1 (cells 1-2) the upper half and tile
    2 (cell 3) the lower right quadrant. Shard s serves shard_tiles[s]."""
    from locator.v1 import locator_pb2 as pb
    return pb.GetTopologyResponse(
        dataset=dataset, tiled=True,
        bounds=pb.BoundingBox(min_x=BOUNDS[0], min_y=BOUNDS[1],
                              max_x=BOUNDS[2], max_y=BOUNDS[3]),
        grid_level=1, fingerprint=0xff,
        tiles=[pb.TopologyTile(first_cell=0, end_cell=1),
               pb.TopologyTile(first_cell=1, end_cell=3),
               pb.TopologyTile(first_cell=3, end_cell=4)],
        shards=[pb.TopologyShard(target=target, tiles=tiles)
                for target, tiles in zip(targets, shard_tiles)],
        complete=complete)


def quadrant_shard(x, y):
    """The shard of three_shard_topology serving (x, y), by the picture:
    0 the lower left quadrant, 1 the upper half, 2 the lower right (points
    outside BOUNDS take the nearest border cell; the middle lines belong to
    the upper and right halves)."""
    if min(max(y, 0), 10) >= 5:
        return 1
    return 2 if min(max(x, 0), 10) >= 5 else 0


# Points over and around BOUNDS: inside each quadrant, on the middle
# lines, on and beyond the borders and corners.
POINTS = [(2, 3), (7, 8), (2, 8), (8, 1), (5, 5), (5, 4.999), (4.999, 5),
          (4.999, 4.999), (0, 0), (10, 10), (0, 10), (10, 0), (-5, 20),
          (-3, -3), (20, 1), (12, 12), (5, -1), (1e300, -1e300), (9.5, 0.5),
          (0.5, 9.5)] + [((i * 7919) % 1300 / 100 - 1.5,
                          (i * 104729) % 1300 / 100 - 1.5)
                         for i in range(200)]


class HilbertKeyTest(unittest.TestCase):

    def test_positions_known_from_the_curve(self):
        from locator_client import _hilbert_index
        quarter = 1 << 30
        # The curve runs from the lower left corner up through the left
        # quadrants, along the upper right one and down to the lower right
        # corner; each quadrant holds a quarter of the positions.
        for (x, y), d in [((0, 0), 0), ((0, 32767), quarter - 1),
                          ((0, 32768), quarter),
                          ((32767, 32768), 2 * quarter - 1),
                          ((32768, 32768), 2 * quarter),
                          ((65535, 32768), 3 * quarter - 1),
                          ((65535, 32767), 3 * quarter),
                          ((65535, 0), 4 * quarter - 1),
                          # The upper corners are in quadrant 1 (then 2) at
                          # every level, which keeps the frame.
                          ((0, 65535), 0x55555555),
                          ((65535, 65535), 0xAAAAAAAA),
                          # The lowest level, in the lower left quadrant,
                          # is turned (x and y exchanged 15 times).
                          ((1, 0), 1), ((1, 1), 2), ((0, 1), 3)]:
            self.assertEqual(_hilbert_index(x, y), d, (x, y))
        # The two top levels: the 4 x 4 curve, row y = 0 first.
        order = [[0, 1, 14, 15], [3, 2, 13, 12], [4, 7, 8, 11],
                 [5, 6, 9, 10]]
        for row in range(4):
            for col in range(4):
                self.assertEqual(
                    _hilbert_index(col * 16384 + 5, row * 16384 + 7) >> 28,
                    order[row][col], (col, row))

    def test_cells_clamp_and_survive_any_double(self):
        from locator_client import _hilbert_cell
        huge = sys.float_info.max
        for v, lo, hi, cell in [
                (0.0, 0.0, 1.0, 0), (1.0, 0.0, 1.0, 65535),
                (0.5, 0.0, 1.0, 32768), (0.5 - 1e-12, 0.0, 1.0, 32767),
                (-3.0, 0.0, 1.0, 0), (7.0, 0.0, 1.0, 65535),
                (math.nan, 0.0, 1.0, 0), (math.inf, 0.0, 1.0, 65535),
                (-math.inf, 0.0, 1.0, 0),
                (3.0, 5.0, 5.0, 0),  # an empty extent
                (0.0, -huge, huge, 32768),  # hi - lo overflows: halves
                (huge, -huge, huge, 65535), (-huge, -huge, huge, 0)]:
            self.assertEqual(_hilbert_cell(v, lo, hi), cell, (v, lo, hi))

    def test_keys_as_the_cpp_header_computes_them(self):
        from locator_client import _hilbert_index, _hilbert_key
        huge = sys.float_info.max
        # Printed by a program of common/hilbert.h's HilbertKey.
        for x, y, box, key in [
                (0.3, 0.7, UNIT, 1979053557),
                (0.123456789, 0.987654321, UNIT, 1454346866),
                (15.0, 49.65, (-180, -90, 180, 90), 2429693341),
                (500123.25, 5499876.5, (497000, 5497000, 503000, 5503000),
                 3581375819),
                (-1, 0.5, UNIT, 1 << 30), (2, -3, UNIT, (1 << 32) - 1),
                (math.nan, 0.25, UNIT, 984263338),
                (0.75, math.inf, UNIT, 2773833045),
                (3, 4, (5, 5, 5, 5), 0),
                (1e307, -1e307, (-1e308, -huge, 1e308, huge), 3575254259),
                (0.4, 0.6, (5.996288294485286e-05, 4.077330972640514e-05,
                            0.9998683728214217, 0.9999331645851757),
                 2105376112)]:
            self.assertEqual(_hilbert_key(x, y, box), key, (x, y, box))
        # And HilbertIndex over 65536 cells of the grid, summed as the C++
        # program summed them.
        total = sum(_hilbert_index(i, (i * 40503 + 12345) & 0xffff) * (i + 1)
                    for i in range(65536)) % (1 << 64)
        self.assertEqual(total, 5841215834374051258)


class ShardMapTest(unittest.TestCase):
    """_shard_map's checks of a topology, and the split and merge of a
    batch by it."""

    def assert_raises_locator_error(self, code, details, call, *args):
        from locator_client import LocatorError
        with self.assertRaises(LocatorError) as raised:
            call(*args)
        self.assertEqual(raised.exception.code, code)
        self.assertEqual(raised.exception.details, details)

    def test_a_dataset_without_shards_to_route_to_needs_no_map(self):
        from locator.v1 import locator_pb2 as pb
        from locator_client import _shard_map
        self.assertIsNone(_shard_map(pb.GetTopologyResponse(
            dataset="one", tiled=False, complete=True,
            shards=[pb.TopologyShard()])))
        self.assertIsNone(_shard_map(three_shard_topology(
            [""], shard_tiles=([0, 1, 2],))))

    def test_an_incomplete_topology_says_which_tile_has_no_shard(self):
        from locator_client import _shard_map
        # A shard started with --tiles lists itself alone.
        self.assert_raises_locator_error(
            "FAILED_PRECONDITION",
            "topology of dataset 'big' is incomplete: tile 1 has no shard; "
            "route through a router (locatord --route)",
            _shard_map, three_shard_topology([""], complete=False,
                                             shard_tiles=([0, 2],)))
        self.assert_raises_locator_error(
            "FAILED_PRECONDITION",
            "topology of dataset 'big' is incomplete; route through a "
            "router (locatord --route)",
            _shard_map, three_shard_topology(["", "b", "c"], complete=False))

    def test_a_malformed_topology_is_internal(self):
        from locator_client import _shard_map
        prefix = "the server's topology of dataset 'big': "
        topology = three_shard_topology(["", "b", "c"])
        topology.grid_level = 16
        self.assert_raises_locator_error(
            "INTERNAL", prefix + "grid level 16 is above 15", _shard_map,
            topology)
        topology = three_shard_topology(["", "b", "c"])
        topology.tiles[1].end_cell = 2
        self.assert_raises_locator_error(
            "INTERNAL",
            prefix + "the tiles do not cover its 4 cells in order from cell 0",
            _shard_map, topology)
        topology = three_shard_topology(["", "b", "c"])
        topology.bounds.max_x = math.inf
        self.assert_raises_locator_error(
            "INTERNAL", prefix + "the bounds must be finite with min <= max",
            _shard_map, topology)
        self.assert_raises_locator_error(
            "INTERNAL", prefix + "shard 2 lists tile 1, which shard 1 lists",
            _shard_map, three_shard_topology(
                ["", "b", "c"], shard_tiles=([0], [1], [1, 2])))
        self.assert_raises_locator_error(
            "INTERNAL", prefix + "shard 0 lists tile 3, which does not exist",
            _shard_map, three_shard_topology(
                ["", "b", "c"], shard_tiles=([0, 3], [1], [2])))

    def test_points_go_to_the_shard_of_their_tile(self):
        from locator_client import _shard_map
        shard_map = _shard_map(three_shard_topology(["", "b", "c"]))
        self.assertEqual(shard_map.targets, ("", "b", "c"))
        for x, y in POINTS:
            self.assertEqual(shard_map.shard_of(x, y), quadrant_shard(x, y),
                             (x, y))

    def test_a_batch_split_over_three_shards_merges_back_in_order(self):
        from locator_client import Location, _merge_batch, _shard_map
        shard_map = _shard_map(three_shard_topology(["", "b", "c"]))
        xs, ys = zip(*POINTS)
        positions = shard_map.split(xs, ys)
        self.assertEqual(len(positions), 3)
        for shard, part in enumerate(positions):
            self.assertEqual(part, sorted(part))
            self.assertGreater(len(part), 10)
            for i in part:
                self.assertEqual(quadrant_shard(*POINTS[i]), shard)
        self.assertEqual(sorted(sum(positions, [])),
                         list(range(len(POINTS))))

        def answer(x, y, shard):
            """A shard's synthesised answer: from the point alone."""
            return Location(type="FACE", triangle_id=hash((x, y)) & 0xffff,
                            vertex_ids=(), barycentric=(), value=x - y,
                            cost=shard)

        # The shards answer in another order than they were split in.
        parts = [(positions[s], [answer(xs[i], ys[i], s)
                                 for i in positions[s]])
                 for s in (2, 0, 1)]
        self.assertEqual(
            _merge_batch(parts, len(POINTS)),
            [answer(x, y, quadrant_shard(x, y)) for x, y in POINTS])

    def test_a_point_that_is_not_finite_is_named_by_its_batch_index(self):
        from locator_client import _shard_map
        shard_map = _shard_map(three_shard_topology(["", "b", "c"]))
        self.assert_raises_locator_error(
            "INVALID_ARGUMENT", "point 2 has a non-finite coordinate "
            "(1.0, nan)", shard_map.split, [1, 2, 1], [1, 2, math.nan])


def make_fake():
    """The fake shard class, made once the stubs are importable."""
    import grpc
    from locator.v1 import locator_pb2 as pb, locator_pb2_grpc

    class FakeShard(locator_pb2_grpc.LocatorServicer):
        """Answers every point from its coordinates alone, as every shard
        of a tile set answers as the whole mesh would; FAILED_PRECONDITION
        for a point of dataset "big" in another shard's tiles (`serves`:
        its shard index in three_shard_topology, None: all points).
        Records its requests;
        `topologies` by dataset; `failure` makes the next LocateBatch
        fail; `barrier`, when set, is waited on by each LocateBatch."""

        def __init__(self, serves):
            self.serves = serves
            self.topologies = {}
            self.requests = []
            self.topology_calls = 0
            self.failure = None
            self.barrier = None

        def _check(self, request, x, y, context):
            if (request.dataset == "big" and self.serves is not None and
                    quadrant_shard(x, y) != self.serves):
                context.abort(grpc.StatusCode.FAILED_PRECONDITION,
                              f"({x}, {y}) is not mine")

        @staticmethod
        def triangle(x, y):
            def column(v):
                return int((min(max(v, -2), 98) + 2) * 100)
            return column(x) * 10000 + column(y)

        def Locate(self, request, context):
            self.requests.append(request)
            x, y = request.point.x, request.point.y
            self._check(request, x, y, context)
            return pb.LocateResponse(
                type=pb.LOCATION_TYPE_FACE, triangle_id=self.triangle(x, y),
                vertex_ids=[1, 2, 3], barycentric=[0.25, 0.25, 0.5],
                value=x * y, cost=pb.Cost(total=int(x) % 7))

        def LocateBatch(self, request, context):
            self.requests.append(request)
            if self.barrier is not None:
                self.barrier.wait()
            if self.failure:
                failure, self.failure = self.failure, None
                context.abort(*failure)
            points = list(zip(request.xs, request.ys))
            for x, y in points:
                self._check(request, x, y, context)
            inside = [0 <= x <= 10 and 0 <= y <= 10 for x, y in points]
            return pb.LocateBatchResponse(
                types=[pb.LOCATION_TYPE_FACE if i else
                       pb.LOCATION_TYPE_OUTSIDE_CONVEX_HULL for i in inside],
                triangle_ids=[self.triangle(x, y) for x, y in points],
                costs=[int(abs(x) + abs(y)) % 11 for x, y in points],
                vertex_ids=[v for x, y in points
                            for v in (int(x) % 5, int(y) % 5, 9)]
                if request.include_vertex_ids else [],
                barycentric=[b for x, y in points for b in (x, y, 1 - x - y)]
                if request.include_barycentric else [],
                values=[x - y + request.interpolation if i else math.nan
                        for (x, y), i in zip(points, inside)]
                if request.include_values else [])

        def GetTopology(self, request, context):
            self.topology_calls += 1
            if request.dataset not in self.topologies:
                context.abort(grpc.StatusCode.NOT_FOUND,
                              f"no dataset '{request.dataset}'")
            return self.topologies[request.dataset]

    return FakeShard, grpc, locator_pb2_grpc


class RoutedClientTest(unittest.TestCase):
    """LocatorClient(route=True) against three fake shards (the first also
    answers GetTopology, as a shard listing itself with an empty target),
    compared with a plain client of a fake serving every point."""

    @classmethod
    def setUpClass(cls):
        FakeShard, cls.grpc, stubs = make_fake()
        cls.servers = []
        cls.shards = [FakeShard(s) for s in range(3)]
        cls.whole = FakeShard(None)
        targets = []
        for fake in cls.shards + [cls.whole]:
            server = cls.grpc.server(futures.ThreadPoolExecutor(max_workers=4))
            stubs.add_LocatorServicer_to_server(fake, server)
            port = server.add_insecure_port("127.0.0.1:0")
            server.start()
            cls.servers.append(server)
            targets.append(f"127.0.0.1:{port}")
        cls.target, cls.whole_target = targets[0], targets[3]
        cls.shard_targets = ["", targets[1], targets[2]]
        from locator.v1 import locator_pb2 as pb
        cls.shards[0].topologies = {
            "big": three_shard_topology(cls.shard_targets),
            "partial": three_shard_topology(
                [""], dataset="partial", complete=False,
                shard_tiles=([0],)),
            "small": pb.GetTopologyResponse(
                dataset="small", tiled=False, complete=True,
                shards=[pb.TopologyShard()])}

    @classmethod
    def tearDownClass(cls):
        for server in cls.servers:
            server.stop(grace=None)

    def setUp(self):
        self.clear_requests()
        self.shards[0].topology_calls = 0

    def clear_requests(self):
        for fake in self.shards + [self.whole]:
            fake.requests.clear()

    def routed(self, dataset="big", **kwargs):
        from locator_client import LocatorClient
        return LocatorClient(self.target, deadline_s=10, dataset=dataset,
                             route=True, **kwargs)

    def plain(self):
        from locator_client import LocatorClient
        return LocatorClient(self.whole_target, deadline_s=10, dataset="big")

    def test_a_routed_batch_answers_as_one_server_keeping_every_field(self):
        xs, ys = zip(*POINTS)
        with self.routed() as routed, self.plain() as plain:
            for flags in [{}, {"vertex_ids": True, "values": True},
                          {"barycentric": True, "values": True,
                           "interpolation": "natural-neighbor"}]:
                self.clear_requests()
                answers = routed.locate_batch(xs, ys, **flags)
                self.assertEqual(answers, plain.locate_batch(xs, ys, **flags))
                (whole,) = self.whole.requests
                for shard, fake in enumerate(self.shards):
                    (part,) = fake.requests
                    self.assertEqual(
                        list(zip(part.xs, part.ys)),
                        [p for p in POINTS if quadrant_shard(*p) == shard])
                    part.ClearField("xs")
                    part.ClearField("ys")
                    expected = type(whole)()
                    expected.CopyFrom(whole)
                    expected.ClearField("xs")
                    expected.ClearField("ys")
                    self.assertEqual(part, expected)
            self.assertEqual(self.whole.requests[0].interpolation, 2)
            self.assertEqual(self.shards[0].topology_calls, 1)
            self.assertEqual(routed.topology().dataset, "big")
            self.assertEqual(len(routed.topology("big").shards), 3)
            self.assertEqual(self.shards[0].topology_calls, 1)

    def test_the_parts_are_sent_before_any_answer_is_awaited(self):
        xs, ys = zip(*POINTS)
        barrier = threading.Barrier(3, timeout=5)
        for fake in self.shards:
            fake.barrier = barrier
        try:
            with self.routed() as routed:
                self.assertEqual(len(routed.locate_batch(xs, ys)),
                                 len(POINTS))
        finally:
            for fake in self.shards:
                fake.barrier = None
        self.assertFalse(barrier.broken)

    def test_locate_goes_to_the_shard_of_the_point(self):
        with self.routed() as routed, self.plain() as plain:
            for x, y in POINTS[:20]:
                self.assertEqual(routed.locate(x, y), plain.locate(x, y))
            for shard, fake in enumerate(self.shards):
                self.assertEqual(
                    [(r.point.x, r.point.y) for r in fake.requests],
                    [p for p in POINTS[:20] if quadrant_shard(*p) == shard])

    def test_parts_only_for_shards_with_points_and_none_for_no_points(self):
        with self.routed() as routed:
            self.assertEqual(routed.locate_batch([], []), [])
            self.assertEqual(len(routed.locate_batch([1, 9], [1, 1])), 2)
        self.assertEqual([len(fake.requests) for fake in self.shards],
                         [1, 0, 1])

    def test_a_shards_failure_names_the_shard(self):
        from locator_client import LocatorError
        self.shards[2].failure = (self.grpc.StatusCode.UNAVAILABLE, "down")
        with self.routed() as routed:
            with self.assertRaises(LocatorError) as raised:
                routed.locate_batch([1, 9, 2], [1, 1, 9])
        self.assertEqual(raised.exception.code, "UNAVAILABLE")
        self.assertEqual(raised.exception.details,
                         f"shard {self.shard_targets[2]}: down")

    def test_an_incomplete_topology_or_an_unknown_dataset_raises(self):
        from locator_client import LocatorError
        with self.routed() as routed:
            with self.assertRaises(LocatorError) as raised:
                routed.locate(1, 1, dataset="partial")
            self.assertEqual(raised.exception.code, "FAILED_PRECONDITION")
            self.assertEqual(
                raised.exception.details,
                "topology of dataset 'partial' is incomplete: tile 1 has no "
                "shard; route through a router (locatord --route)")
            with self.assertRaises(LocatorError) as raised:
                routed.locate(1, 1, dataset="absent")
            self.assertEqual(raised.exception.code, "NOT_FOUND")
        self.assertEqual([len(fake.requests) for fake in self.shards],
                         [0, 0, 0])

    def test_points_in_a_crs_are_routed_where_proj_maps_them(self):
        from pyproj import Transformer
        # A topology in Web Mercator metres over [0, 10]^2, queried in
        # lon/lat: each point goes to the shard of its quadrant in metres,
        # sent as it came. Points within a millimetre of the middle lines
        # are left out (a round trip through lon/lat may cross them).
        self.shards[0].topologies["mercator"] = three_shard_topology(
            self.shard_targets, dataset="mercator")
        self.shards[0].topologies["mercator"].crs = "EPSG:3857"
        metres = [(x, y) for x, y in POINTS[:120]
                  if abs(x) < 1e6 and abs(y) < 1e6 and
                  abs(x - 5) > 1e-3 and abs(y - 5) > 1e-3]
        lon_lat = Transformer.from_crs("EPSG:3857", "EPSG:4326",
                                       always_xy=True)
        xs, ys = lon_lat.transform(*zip(*metres))
        with self.routed(dataset="mercator", crs="EPSG:4326") as routed:
            self.assertEqual(len(routed.locate_batch(xs, ys)), len(metres))
            for x, y in zip(xs[:10], ys[:10]):
                routed.locate(x, y)
        for shard, fake in enumerate(self.shards):
            batch, *singles = fake.requests
            mine = [i for i, p in enumerate(metres)
                    if quadrant_shard(*p) == shard]
            self.assertEqual(list(zip(batch.xs, batch.ys)),
                             [(xs[i], ys[i]) for i in mine])
            self.assertEqual((batch.dataset, batch.crs),
                             ("mercator", "EPSG:4326"))
            self.assertEqual([(r.point.x, r.point.y) for r in singles],
                             [(xs[i], ys[i]) for i in mine if i < 10])

    def test_points_that_cannot_be_mapped_go_whole_to_the_first_shard(self):
        # The dataset has no CRS, the crs is unknown, a point is outside
        # the area of use: the first shard refuses the call in the server's
        # words.
        self.shards[0].topologies["mercator"] = three_shard_topology(
            self.shard_targets, dataset="mercator")
        self.shards[0].topologies["mercator"].crs = "EPSG:3857"
        self.shards[0].topologies["no-crs"] = three_shard_topology(
            self.shard_targets, dataset="no-crs")
        for dataset, crs, xs, ys in [
                ("no-crs", "EPSG:4326", [1, 9], [1, 1]),
                ("mercator", "EPSG:999999", [1, 9], [1, 1]),
                ("mercator", "EPSG:4326", [1e-5, 0], [1e-5, -89.9])]:
            self.clear_requests()
            with self.routed(dataset=dataset, crs=crs) as routed:
                routed.locate_batch(xs, ys)
            (whole,) = self.shards[0].requests
            self.assertEqual((list(whole.xs), list(whole.ys), whole.crs),
                             (xs, ys, crs), (dataset, crs))
            self.assertEqual([len(fake.requests) for fake in self.shards],
                             [1, 0, 0])
        # A point that is not finite is refused as without a crs.
        from locator_client import LocatorError
        with self.routed(dataset="mercator", crs="EPSG:4326") as routed:
            with self.assertRaises(LocatorError) as raised:
                routed.locate_batch([1e-5, math.nan], [1e-5, 0])
        self.assertEqual(raised.exception.code, "INVALID_ARGUMENT")

    def test_without_pyproj_points_in_a_crs_are_refused(self):
        from locator_client import LocatorError
        self.shards[0].topologies["mercator"] = three_shard_topology(
            self.shard_targets, dataset="mercator")
        self.shards[0].topologies["mercator"].crs = "EPSG:3857"
        saved = sys.modules.get("pyproj")
        sys.modules["pyproj"] = None  # import pyproj raises ImportError
        try:
            with self.routed(dataset="mercator", crs="EPSG:4326") as routed:
                with self.assertRaises(LocatorError) as raised:
                    routed.locate(1e-5, 1e-5)
        finally:
            sys.modules["pyproj"] = saved
        self.assertEqual(raised.exception.code, "INVALID_ARGUMENT")
        self.assertIn("python3-pyproj", raised.exception.details)
        self.assertIn("locatord --route", raised.exception.details)
        self.assertEqual([len(fake.requests) for fake in self.shards],
                         [0, 0, 0])

    def test_a_dataset_that_is_not_tiled_is_called_on_the_target(self):
        # Points of every quadrant, all to the target (shard 0), in a crs.
        with self.routed(dataset="small", crs="EPSG:3857") as routed:
            self.assertEqual(len(routed.locate_batch([1, 8], [1, 8])), 2)
            self.assertEqual(routed.locate(8, 3).triangle_id,
                             self.whole.triangle(8, 3))
        (batch, single) = self.shards[0].requests
        self.assertEqual(list(batch.xs), [1, 8])
        self.assertEqual((batch.dataset, batch.crs), ("small", "EPSG:3857"))
        self.assertEqual((single.point.x, single.dataset), (8, "small"))
        self.assertEqual([len(fake.requests) for fake in self.shards[1:]],
                         [0, 0])

    def test_close_closes_the_shard_channels(self):
        with self.routed() as routed:
            routed.locate_batch([1, 9, 2], [1, 1, 9])
        with self.assertRaises(ValueError):  # grpc's closed channel
            routed.locate(9, 1)


def main():
    global PYTHON_DIR
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    PYTHON_DIR = sys.argv[1]
    sys.path.insert(0, PYTHON_DIR)
    unittest.main(argv=sys.argv[:1], verbosity=2)


if __name__ == "__main__":
    main()
