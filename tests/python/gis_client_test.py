#!/usr/bin/env python3
"""ctest: the Python client's dataset= and crs= against a live locatord
serving a GeoPackage in UTM zone 33N (EPSG:32633), and beside it a DEM.

Makes the GeoPackage as the README's quick start does: a CSV of x, y, z
turned into a layer by ogr2ogr with -a_srs EPSG:32633. Points queried in
lon/lat (crs="EPSG:4326", client-wide or per call) must get the answers of
the same points projected by cs2cs beforehand. The DEM, an ASCII grid with
a nodata hole served as dem=dem.asc?a_srs=EPSG:32633&max_error=0.5, must
come with its simplification certificate in stats() and list_datasets().

Usage: gis_client_test.py LOCATORD PYTHON_DIR OGR2OGR CS2CS
"""

import math
import os
import subprocess
import sys
import tempfile
import unittest

from locatord_process import Locatord

LOCATORD = PYTHON_DIR = OGR2OGR = CS2CS = None  # set in main()

# Lon/lat points over the survey (centred at 15°E, 49.6525°N).
LON_LAT = [(15.0, 49.6525), (15.0031, 49.6541), (14.9977, 49.6509),
           (15.0012, 49.6498)]


def height(x, y):
    """The survey's z: a hill around (500000, 5500000)."""
    r2 = (x - 500000) ** 2 + (y - 5500000) ** 2
    return 400 + 50 * math.exp(-r2 / (2 * 300 ** 2))


def project(points):
    """`points` (lon, lat) in UTM 33N by cs2cs, which takes lat, lon."""
    text = "".join(f"{lat!r} {lon!r}\n" for lon, lat in points)
    result = subprocess.run(
        [CS2CS, "-f", "%.12f", "EPSG:4326", "EPSG:32633"], input=text,
        capture_output=True, text=True, check=True)
    return [tuple(map(float, line.split()[:2]))
            for line in result.stdout.splitlines()]


class GisClientTest(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        cls.work = tempfile.TemporaryDirectory()
        csv = os.path.join(cls.work.name, "terrain.csv")
        with open(csv, "w") as out:
            out.write("x,y,z\n")
            for i in range(-6, 7):
                for j in range(-6, 7):
                    # A small jitter keeps the grid from being cocircular.
                    x = 500000 + 100 * i + (j % 3) * 3.0
                    y = 5500000 + 100 * j + (i % 5) * 2.0
                    out.write(f"{x!r},{y!r},{height(x, y)!r}\n")
        gpkg = os.path.join(cls.work.name, "terrain.gpkg")
        subprocess.run(
            [OGR2OGR, "-f", "GPKG", gpkg, csv, "-nln", "terrain", "-a_srs",
             "EPSG:32633", "-oo", "X_POSSIBLE_NAMES=x", "-oo",
             "Y_POSSIBLE_NAMES=y", "-oo", "Z_POSSIBLE_NAMES=z"],
            check=True, capture_output=True)
        dem = os.path.join(cls.work.name, "dem.asc")
        with open(dem, "w") as out:
            out.write("ncols 40\nnrows 30\nxllcorner 499000\n"
                      "yllcorner 5499000\ncellsize 50\nNODATA_value -9999\n")
            for row in range(30):
                out.write(" ".join(
                    "-9999" if 10 <= row < 14 and 20 <= col < 25 else
                    repr(height(499025 + 50 * col, 5500475 - 50 * row))
                    for col in range(40)) + "\n")
        cls.dem_pixels = 40 * 30 - 4 * 5
        cls.server = Locatord(
            LOCATORD, ["--dataset", gpkg, "--dataset",
                       f"dem={dem}?a_srs=EPSG:32633&max_error=0.5"],
            cls.work.name)

    @classmethod
    def tearDownClass(cls):
        cls.server.stop()
        cls.work.cleanup()

    def assert_same_answer(self, lon_lat, projected):
        self.assertEqual(lon_lat.type, "FACE")
        self.assertEqual(lon_lat.triangle_id, projected.triangle_id)
        self.assertEqual(lon_lat.vertex_ids, projected.vertex_ids)
        self.assertAlmostEqual(lon_lat.value, projected.value, delta=1e-6)
        self.assertGreater(lon_lat.value, 400)

    def test_client_wide_crs_answers_as_the_projected_points(self):
        from locator_client import LocatorClient
        utm = project(LON_LAT)
        with LocatorClient(self.server.target, crs="EPSG:4326",
                           dataset="") as client:
            for (lon, lat), (x, y) in zip(LON_LAT, utm):
                self.assert_same_answer(client.locate(lon, lat),
                                        client.locate(x, y, crs=""))
            batch = client.locate_batch([p[0] for p in LON_LAT],
                                        [p[1] for p in LON_LAT],
                                        vertex_ids=True, values=True)
            projected = client.locate_batch(
                [p[0] for p in utm], [p[1] for p in utm], vertex_ids=True,
                values=True, crs="")
            for answer, expected in zip(batch, projected):
                self.assert_same_answer(answer, expected)

    def test_per_call_crs_and_the_datasets_crs_in_stats(self):
        from locator_client import LocatorClient, LocatorError
        with LocatorClient(self.server.target) as client:
            (x, y), = project(LON_LAT[:1])
            self.assert_same_answer(
                client.locate(*LON_LAT[0], crs="EPSG:4326"),
                client.locate(x, y))
            crs = client.stats(dataset="").dataset.crs
            self.assertEqual(crs.epsg_code, 32633)
            self.assertEqual(crs.name, "WGS 84 / UTM zone 33N")
            with self.assertRaises(LocatorError) as raised:
                client.locate(15, 49.65, crs="EPSG:999999")
            self.assertEqual(raised.exception.code, "INVALID_ARGUMENT")
            self.assertIn("EPSG:999999", raised.exception.details)

    def test_the_dems_certificate_passes_through(self):
        from locator_client import LocatorClient
        with LocatorClient(self.server.target) as client:
            stats = client.stats(dataset="dem").dataset
            self.assertTrue(stats.HasField("simplification"))
            certificate = stats.simplification
            self.assertEqual(certificate.source_samples, self.dem_pixels)
            self.assertLessEqual(certificate.max_error, 0.5)
            self.assertEqual(certificate.target_error, 0.5)
            self.assertLess(certificate.vertices, self.dem_pixels)
            self.assertEqual(certificate.vertices, stats.vertices)
            self.assertEqual(stats.crs.epsg_code, 32633)
            self.assertFalse(
                client.stats(dataset="").dataset.HasField("simplification"))
            listed = {d.name: d for d in client.list_datasets()}
            self.assertEqual(listed["dem"].stats.simplification, certificate)

    def test_profile_in_lon_lat_and_grid_against_the_live_server(self):
        from locator_client import LocatorClient
        with LocatorClient(self.server.target) as client:
            line = [(14.9985, 49.6495), (15.0015, 49.6555)]
            (x0, y0), (x1, y1) = project(line)
            lon_lat = client.profile(line, samples=7, crs="EPSG:4326")
            projected = client.profile([(x0, y0), (x1, y1)], samples=7)
            # The same line, so the same breakpoints, up to the projection.
            self.assertEqual(lon_lat.crossings, projected.crossings)
            self.assertGreater(lon_lat.crossings, 5)
            self.assertAlmostEqual(lon_lat.length, math.hypot(x1 - x0, y1 - y0),
                                   delta=1e-6)
            for a, b in zip(lon_lat.breakpoints, projected.breakpoints):
                self.assertAlmostEqual(a.value, b.value, delta=1e-6)
                self.assertEqual(a.triangle_id, b.triangle_id)
            self.assertEqual(len(lon_lat.samples), 7)
            self.assertEqual(lon_lat.gaps, ())
            # Every breakpoint's value is the surface's there.
            for point in projected.breakpoints:
                self.assertAlmostEqual(
                    point.value, client.locate(point.x, point.y).value,
                    delta=1e-9)

            values, header = client.grid((499500, 5499500, 500500, 5500500),
                                         width=20, height=10, nodata=-1)
            self.assertEqual(values.shape, (10, 20))
            self.assertIn("UTM zone 33N", header.crs_wkt)
            for row in range(10):
                for col in range(20):
                    x = header.box[0] + (col + 0.5) * header.cell_width
                    y = header.box[3] - (row + 0.5) * header.cell_height
                    expected = client.locate(x, y).value
                    self.assertAlmostEqual(values[row, col], expected,
                                           delta=1e-9)
            natural, _ = client.grid((499500, 5499500, 500500, 5500500),
                                     width=20, height=10,
                                     interpolation="natural-neighbor")
            self.assertTrue(((natural > 400) & (natural < 451)).all())


def main():
    global LOCATORD, PYTHON_DIR, OGR2OGR, CS2CS
    if len(sys.argv) != 5:
        sys.exit(__doc__)
    LOCATORD, PYTHON_DIR, OGR2OGR, CS2CS = sys.argv[1:]
    sys.path.insert(0, PYTHON_DIR)
    unittest.main(argv=sys.argv[:1], verbosity=2)


if __name__ == "__main__":
    main()
