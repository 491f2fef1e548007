#!/usr/bin/env python3
"""ctest: the Python client and its example against a live locatord.

Writes a dataset whose z is the plane z = 1 + 2x + 3y (linear
interpolation reproduces a plane, so every answer inside the hull is
known), starts locatord on it on a port the OS picks, and runs
client/python/examples/locate_csv.py and the locator_client module on
known points.

Usage: locate_csv_test.py LOCATORD PYTHON_DIR EXAMPLE
(PYTHON_DIR holds the generated stubs and locator_client.py.)
"""

import os
import random
import subprocess
import sys
import tempfile
import unittest

from locatord_process import Locatord

LOCATORD = PYTHON_DIR = EXAMPLE = None  # set from the command line in main()


def plane(x, y):
    return 1 + 2 * x + 3 * y


# The unit square's corners (so the hull is the square) and points inside.
_rng = random.Random(7)
POINTS = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] + [
    (_rng.random(), _rng.random()) for _ in range(200)]


def start_server(work):
    """locatord on the plane dataset, written to `work`."""
    dataset = os.path.join(work, "plane.csv")
    with open(dataset, "w") as out:
        out.write("x,y,z\n")
        for x, y in POINTS:
            out.write(f"{x!r},{y!r},{plane(x, y)!r}\n")
    return Locatord(LOCATORD, ["--dataset", dataset], work)


class LocateCsvTest(unittest.TestCase):
    """The example's output and errors, and the module's calls."""

    @classmethod
    def setUpClass(cls):
        cls.work = tempfile.TemporaryDirectory()
        cls.server = start_server(cls.work.name)

    @classmethod
    def tearDownClass(cls):
        cls.server.stop()
        cls.work.cleanup()

    def run_example(self, points_text):
        """Runs the example on a file holding `points_text`."""
        path = os.path.join(self.work.name, "points.csv")
        with open(path, "w") as out:
            out.write(points_text)
        env = dict(os.environ, PYTHONPATH=PYTHON_DIR)
        return subprocess.run(
            [sys.executable, EXAMPLE, "--target", self.server.target,
             "--chunk", "2", path],
            env=env, capture_output=True, text=True, timeout=60, check=False)

    def rows(self, points_text):
        """The example's output rows as dicts; it must succeed."""
        result = self.run_example(points_text)
        self.assertEqual(result.returncode, 0, result.stderr)
        header, *lines = result.stdout.splitlines()
        self.assertEqual(header, "x,y,type,triangle_id,v0,v1,v2,z")
        return [dict(zip(header.split(","), line.split(","))) for line in lines]

    def test_points_at_vertices_give_the_vertex_z_exactly(self):
        picked = [4, 17, 2]
        rows = self.rows("".join(f"{POINTS[i][0]!r},{POINTS[i][1]!r}\n"
                                 for i in picked))
        self.assertEqual(len(rows), len(picked))
        for i, row in zip(picked, rows):
            self.assertEqual(row["type"], "VERTEX", row)
            self.assertIn(str(i), (row["v0"], row["v1"], row["v2"]), row)
            self.assertEqual(float(row["z"]), plane(*POINTS[i]), row)

    def test_points_inside_interpolate_the_plane(self):
        queries = [(0.3, 0.6), (0.71, 0.12), (0.5, 0.5)]
        rows = self.rows("".join(f"{x},{y}\n" for x, y in queries))
        for (x, y), row in zip(queries, rows):
            self.assertIn(row["type"], ("FACE", "EDGE", "VERTEX"), row)
            self.assertAlmostEqual(float(row["z"]), plane(x, y), places=9)

    def test_point_outside_the_hull_has_no_z(self):
        (row,) = self.rows("5,5\n")
        self.assertEqual(row["type"], "OUTSIDE_CONVEX_HULL")
        self.assertEqual(row["z"], "")

    def test_header_comments_and_blank_lines_are_skipped(self):
        rows = self.rows("x,y\n# a comment\n\n0.25,0.25\n")
        self.assertEqual(len(rows), 1)
        self.assertAlmostEqual(float(rows[0]["z"]), plane(0.25, 0.25))

    def test_nan_point_is_a_clear_error(self):
        result = self.run_example("0.5,0.5\n0.1,0.1\n0.2,0.2\nnan,0.5\n")
        self.assertEqual(result.returncode, 1, result.stdout)
        # The failing batch is the second (--chunk 2): its point 1, line 4.
        self.assertRegex(result.stderr,
                         r"^error: INVALID_ARGUMENT: point 1 .*non-finite.*"
                         r"from line 3 of ")

    def test_unparsable_line_is_an_input_error(self):
        result = self.run_example("0.5,0.5\n0.5,abc\n")
        self.assertEqual(result.returncode, 2)
        self.assertIn("points.csv:2: expected x,y", result.stderr)

    def test_module_locates_one_point_and_checks_batch_shape(self):
        from locator_client import LocatorClient
        with LocatorClient(self.server.target, deadline_s=5) as client:
            here = client.locate(*POINTS[9])
            self.assertEqual(here.type, "VERTEX")
            self.assertIn(9, here.vertex_ids)
            self.assertEqual(here.value, plane(*POINTS[9]))
            self.assertEqual(len(here.barycentric), 3)
            self.assertGreater(here.cost, 0)
            (batch,) = client.locate_batch([0.5], [0.5], barycentric=True)
            self.assertEqual(len(batch.barycentric), 3)
            self.assertEqual(batch.vertex_ids, ())
            self.assertIsNone(batch.value)  # values not asked for
            with self.assertRaises(ValueError):
                client.locate_batch([0.1, 0.2], [0.3])
            self.assertTrue(client.stats().dataset.has_values)


def main():
    global LOCATORD, PYTHON_DIR, EXAMPLE
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    LOCATORD, PYTHON_DIR, EXAMPLE = sys.argv[1:]
    sys.path.insert(0, PYTHON_DIR)
    unittest.main(argv=sys.argv[:1], verbosity=2)


if __name__ == "__main__":
    main()
