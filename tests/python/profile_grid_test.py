#!/usr/bin/env python3
"""ctest: the Python client's dataset=, crs=, interpolation=,
list_datasets(), profile() and grid() against a fake Locator service in
this process, whose answers are computed from the request (the real
server's Profile and Grid come later).

Usage: profile_grid_test.py PYTHON_DIR
(PYTHON_DIR holds the generated stubs and locator_client.py.)
"""

import math
import sys
import unittest
from concurrent import futures

PYTHON_DIR = None  # set in main()
ROWS_PER_MESSAGE = 3


def surface(x, y):
    return 1000 + x + 2 * y


def cell_value(col, row, nodata):
    """The fake's cell (col, row): nodata on every fifth diagonal."""
    return nodata if (col + row) % 5 == 0 else row * 1000.0 + col + 0.5


def make_fake():
    """The fake service class, made once the stubs are importable."""
    import grpc
    from locator.v1 import locator_pb2 as pb, locator_pb2_grpc

    class FakeLocator(locator_pb2_grpc.LocatorServicer):
        """Records the last request of each method; `failures` makes the
        next call of a method fail; `drop_last_grid_message` ends the next
        Grid stream early."""

        def __init__(self):
            self.requests = {}
            self.failures = {}
            self.drop_last_grid_message = False

        def _take(self, method, request, context):
            self.requests[method] = request
            failure = self.failures.pop(method, None)
            if failure:
                context.abort(*failure)

        def Locate(self, request, context):
            self._take("Locate", request, context)
            return pb.LocateResponse(
                type=pb.LOCATION_TYPE_FACE, triangle_id=1,
                value=surface(request.point.x, request.point.y))

        def LocateBatch(self, request, context):
            self._take("LocateBatch", request, context)
            n = len(request.xs)
            return pb.LocateBatchResponse(
                types=[pb.LOCATION_TYPE_FACE] * n, triangle_ids=[1] * n,
                costs=[1] * n,
                values=[surface(x, y) for x, y in zip(request.xs, request.ys)]
                if request.include_values else [])

        def GetStats(self, request, context):
            self._take("GetStats", request, context)
            return pb.GetStatsResponse(strategy="fake")

        def ListDatasets(self, request, context):
            self._take("ListDatasets", request, context)
            return pb.ListDatasetsResponse(datasets=[
                pb.DatasetEntry(
                    name="terrain", is_default=True, serving=True,
                    strategy="self-tuning", generation=3,
                    stats=pb.DatasetStats(
                        input_points=225, triangles=416,
                        crs=pb.CrsStats(name="WGS 84 / UTM zone 33N",
                                        epsg_code=32633))),
                pb.DatasetEntry(name="bedrock")])

        def Profile(self, request, context):
            self._take("Profile", request, context)
            (x0, y0), (x1, y1) = [(v.x, v.y) for v in request.vertices[:2]]
            length = math.hypot(x1 - x0, y1 - y0)
            return pb.ProfileResponse(
                breakpoints=[
                    pb.ProfilePoint(
                        kind=pb.PROFILE_POINT_KIND_LINE_VERTEX,
                        point=pb.Point(x=x0, y=y0), distance=0,
                        value=surface(x0, y0), triangle_id=7),
                    pb.ProfilePoint(
                        kind=pb.PROFILE_POINT_KIND_EDGE_CROSSING,
                        point=pb.Point(x=(x0 + x1) / 2, y=(y0 + y1) / 2),
                        distance=length / 2, triangle_id=-1),
                    pb.ProfilePoint(
                        kind=pb.PROFILE_POINT_KIND_LINE_VERTEX,
                        point=pb.Point(x=x1, y=y1), distance=length,
                        segment=0, triangle_id=-1)],
                samples=[pb.ProfilePoint(
                    kind=pb.PROFILE_POINT_KIND_SAMPLE,
                    point=pb.Point(x=x0, y=y0), distance=0,
                    value=surface(x0, y0), triangle_id=7)
                    for _ in range(request.samples)],
                gaps=[pb.ProfileGap(
                    from_distance=length / 2, to_distance=length,
                    reason=pb.LOCATION_TYPE_OUTSIDE_DOMAIN)],
                length=length, crossings=1)

        def Grid(self, request, context):
            self._take("Grid", request, context)
            box = request.box
            if request.cell_size > 0:
                cell_w = cell_h = request.cell_size
                width = math.ceil((box.max_x - box.min_x) / cell_w)
                height = math.ceil((box.max_y - box.min_y) / cell_h)
                grown = pb.BoundingBox(
                    min_x=box.min_x, max_x=box.min_x + width * cell_w,
                    max_y=box.max_y, min_y=box.max_y - height * cell_h)
            else:
                width, height, grown = request.width, request.height, box
                cell_w = (box.max_x - box.min_x) / width
                cell_h = (box.max_y - box.min_y) / height
            nodata = request.nodata if request.HasField("nodata") else math.nan
            header = pb.GridHeader(width=width, height=height, box=grown,
                                   cell_width=cell_w, cell_height=cell_h,
                                   nodata=nodata, crs_wkt="FAKE WKT")
            firsts = list(range(0, height, ROWS_PER_MESSAGE))[::-1]
            if self.drop_last_grid_message:
                self.drop_last_grid_message = False
                firsts.pop()
            for i, first in enumerate(firsts):
                rows = min(ROWS_PER_MESSAGE, height - first)
                yield pb.GridResponse(
                    header=header if i == 0 else None, first_row=first,
                    rows=rows,
                    values=[cell_value(col, row, nodata)
                            for row in range(first, first + rows)
                            for col in range(width)])

    return FakeLocator, grpc, pb, locator_pb2_grpc


class ProfileGridTest(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        FakeLocator, grpc, cls.pb, stubs = make_fake()
        cls.grpc = grpc
        cls.fake = FakeLocator()
        cls.server = grpc.server(futures.ThreadPoolExecutor(max_workers=4))
        stubs.add_LocatorServicer_to_server(cls.fake, cls.server)
        port = cls.server.add_insecure_port("127.0.0.1:0")
        cls.server.start()
        cls.target = f"127.0.0.1:{port}"

    @classmethod
    def tearDownClass(cls):
        cls.server.stop(grace=None)

    def client(self, **kwargs):
        from locator_client import LocatorClient
        return LocatorClient(self.target, deadline_s=10, **kwargs)

    def test_dataset_and_crs_are_client_defaults_calls_may_override(self):
        with self.client(dataset="terrain", crs="EPSG:4326") as client:
            self.assertEqual(client.locate(15, 49.5).value, 1114)
            request = self.fake.requests["Locate"]
            self.assertEqual((request.dataset, request.crs),
                             ("terrain", "EPSG:4326"))
            client.locate(1, 2, dataset="bedrock", crs="")
            request = self.fake.requests["Locate"]
            self.assertEqual((request.dataset, request.crs), ("bedrock", ""))
            (answer,) = client.locate_batch([1], [2], values=True,
                                            crs="EPSG:3857")
            self.assertEqual(answer.value, 1005)
            request = self.fake.requests["LocateBatch"]
            self.assertEqual((request.dataset, request.crs),
                             ("terrain", "EPSG:3857"))
            self.assertEqual(client.stats().strategy, "fake")
            self.assertEqual(self.fake.requests["GetStats"].dataset, "terrain")
            client.stats(dataset="bedrock")
            self.assertEqual(self.fake.requests["GetStats"].dataset, "bedrock")
        with self.client() as client:
            client.locate(1, 2)
            request = self.fake.requests["Locate"]
            self.assertEqual((request.dataset, request.crs), ("", ""))

    def test_interpolation_names(self):
        pb = self.pb
        with self.client() as client:
            for name, number in [
                    (None, pb.INTERPOLATION_UNSPECIFIED),
                    ("linear", pb.INTERPOLATION_LINEAR),
                    ("natural-neighbor", pb.INTERPOLATION_NATURAL_NEIGHBOR),
                    ("nearest", pb.INTERPOLATION_NEAREST)]:
                client.locate(0, 0, interpolation=name)
                self.assertEqual(
                    self.fake.requests["Locate"].interpolation, number)
                client.locate_batch([0], [0], interpolation=name)
                self.assertEqual(
                    self.fake.requests["LocateBatch"].interpolation, number)
            with self.assertRaisesRegex(ValueError, "'cubic'"):
                client.locate(0, 0, interpolation="cubic")

    def test_list_datasets(self):
        with self.client() as client:
            terrain, bedrock = client.list_datasets()
        self.assertEqual(terrain.name, "terrain")
        self.assertTrue(terrain.is_default)
        self.assertTrue(terrain.serving)
        self.assertEqual((terrain.strategy, terrain.generation),
                         ("self-tuning", 3))
        self.assertEqual(terrain.stats.input_points, 225)
        self.assertEqual(terrain.stats.crs.epsg_code, 32633)
        self.assertEqual(bedrock.name, "bedrock")
        self.assertFalse(bedrock.is_default or bedrock.serving)

    def test_profile(self):
        with self.client(dataset="terrain", crs="EPSG:4326") as client:
            profile = client.profile([(0, 0), (30, 40)], samples=2,
                                     interpolation="nearest")
        request = self.fake.requests["Profile"]
        self.assertEqual([(v.x, v.y) for v in request.vertices],
                         [(0, 0), (30, 40)])
        self.assertEqual(request.samples, 2)
        self.assertEqual((request.dataset, request.crs),
                         ("terrain", "EPSG:4326"))
        self.assertEqual(request.interpolation, self.pb.INTERPOLATION_NEAREST)
        self.assertEqual((profile.length, profile.crossings), (50, 1))
        first, middle, last = profile.breakpoints
        self.assertEqual(
            (first.kind, first.x, first.y, first.distance, first.value,
             first.triangle_id), ("LINE_VERTEX", 0, 0, 0, 1000, 7))
        self.assertEqual((middle.kind, middle.x, middle.y, middle.distance),
                         ("EDGE_CROSSING", 15, 20, 25))
        self.assertIsNone(middle.value)
        self.assertEqual((last.kind, last.distance, last.segment),
                         ("LINE_VERTEX", 50, 0))
        self.assertEqual([s.kind for s in profile.samples],
                         ["SAMPLE", "SAMPLE"])
        (gap,) = profile.gaps
        self.assertEqual((gap.from_distance, gap.to_distance, gap.reason),
                         (25, 50, "OUTSIDE_DOMAIN"))

    def expected_raster(self, width, height, nodata):
        import numpy
        return numpy.array([[cell_value(col, row, nodata)
                             for col in range(width)]
                            for row in range(height)])

    def test_grid_by_size_has_every_value_at_its_place(self):
        import numpy
        with self.client(dataset="terrain") as client:
            values, header = client.grid((500000, 5499800, 500370, 5500000),
                                         width=37, height=20, nodata=-9999,
                                         interpolation="natural-neighbor")
        request = self.fake.requests["Grid"]
        self.assertEqual((request.width, request.height, request.cell_size),
                         (37, 20, 0))
        self.assertEqual((request.box.min_x, request.box.min_y,
                          request.box.max_x, request.box.max_y),
                         (500000, 5499800, 500370, 5500000))
        self.assertTrue(request.HasField("nodata"))
        self.assertEqual(request.nodata, -9999)
        self.assertEqual(request.dataset, "terrain")
        self.assertEqual(request.interpolation,
                         self.pb.INTERPOLATION_NATURAL_NEIGHBOR)
        self.assertEqual(values.shape, (20, 37))
        self.assertEqual(values.dtype, numpy.float64)
        numpy.testing.assert_array_equal(
            values, self.expected_raster(37, 20, -9999))
        self.assertEqual((header.width, header.height), (37, 20))
        self.assertEqual(header.geotransform,
                         (500000, 10, 0, 5500000, 0, -10))
        self.assertEqual(header.nodata, -9999)
        self.assertEqual(header.crs_wkt, "FAKE WKT")

    def test_grid_by_cell_size_with_nan_nodata(self):
        import numpy
        with self.client() as client:
            values, header = client.grid((-50, -20, 50, 30), cell_size=7)
        request = self.fake.requests["Grid"]
        self.assertEqual((request.width, request.height, request.cell_size),
                         (0, 0, 7))
        self.assertFalse(request.HasField("nodata"))
        self.assertEqual(values.shape, (8, 15))
        self.assertEqual(header.box, (-50, -26, 55, 30))
        numpy.testing.assert_array_equal(
            values, self.expected_raster(15, 8, math.nan))
        self.assertEqual(int(numpy.isnan(values).sum()), 24)

    def test_grid_needs_a_size_one_way(self):
        with self.client() as client:
            for kwargs in [{}, {"width": 5}, {"width": 5, "height": 5,
                                              "cell_size": 1}]:
                with self.assertRaisesRegex(ValueError, "width and height"):
                    client.grid((0, 0, 1, 1), **kwargs)

    def test_errors_raise_locator_errors(self):
        from locator_client import LocatorError
        code = self.grpc.StatusCode
        with self.client() as client:
            for method, status, call in [
                    ("Grid", code.RESOURCE_EXHAUSTED,
                     lambda: client.grid((0, 0, 1, 1), width=9, height=9)),
                    ("Grid", code.INVALID_ARGUMENT,
                     lambda: client.grid((0, 0, 1, 1), width=9, height=9)),
                    ("Profile", code.RESOURCE_EXHAUSTED,
                     lambda: client.profile([(0, 0), (1, 1)]))]:
                self.fake.failures[method] = (status, "told to fail")
                with self.assertRaises(LocatorError) as raised:
                    call()
                self.assertEqual(raised.exception.code, status.name)
                self.assertEqual(raised.exception.details, "told to fail")
            self.fake.drop_last_grid_message = True
            with self.assertRaises(LocatorError) as raised:
                client.grid((0, 0, 1, 1), width=4, height=10)
            self.assertEqual(raised.exception.code, "INTERNAL")
            self.assertEqual(raised.exception.details,
                             "the server's grid stream: ended after 7 of "
                             "10 rows")


def main():
    global PYTHON_DIR
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    PYTHON_DIR = sys.argv[1]
    sys.path.insert(0, PYTHON_DIR)
    unittest.main(argv=sys.argv[:1], verbosity=2)


if __name__ == "__main__":
    main()
