#!/usr/bin/env python3
"""ctest: the Python client's routing against live locatords.

Builds a tile set of 20000 uniform points in 10 tiles (locator-build
--tile-points 2000) and serves it four ways: two shards (--tiles 0/2 and
1/2), a router in front of them (--route --shards), and one locatord
serving it whole. A routing client pointed at a shard, whose topology
lists that shard alone, must refuse; one pointed at the router must send
the points straight to the shards (it still answers once the router is
stopped) and get the whole server's answers (costs aside: they are each
server's own work).
A second tile set, in UTM, is queried in lon/lat: the client routes the
points where PROJ (pyproj) puts them in UTM.

Usage: routing_e2e_test.py LOCATORD LOCATOR_BUILD PYTHON_DIR
"""

import dataclasses
import os
import random
import subprocess
import sys
import tempfile
import unittest

from locatord_process import Locatord

LOCATORD = LOCATOR_BUILD = PYTHON_DIR = None  # set in main()


def without_costs(locations):
    return [dataclasses.replace(location, cost=0) for location in locations]


def places(locations):
    """What two servers must agree on (the C++ tests' Disagreement): all
    but the cost, except that a point on a vertex or an edge may be
    answered in any triangle holding it, so there only the vertices it
    lies on, their weights and the value count (to 1e-9)."""
    def place(location):
        if location.type not in ("VERTEX", "EDGE"):
            return dataclasses.replace(location, cost=0)
        on = frozenset((v, round(b, 9)) for v, b in
                       zip(location.vertex_ids, location.barycentric) if b)
        value = None if location.value is None else round(location.value, 9)
        return (location.type, on, value)

    return [place(location) for location in locations]


class TileSetServers(unittest.TestCase):
    """A test class over a tile set built in cls.work (setUpClass makes
    it): two shards of it (--tiles 0/2 and 1/2), a router over them and
    one locatord serving it whole, each logging in a directory of its
    own."""

    @classmethod
    def serve(cls, tile_set, name):
        """Serves the tile set in directory `tile_set` as dataset `name`:
        cls.shards, cls.router and cls.whole."""
        dataset = f"{name}=" + os.path.join(tile_set, "manifest.json")
        cls.servers = []

        def start(server_name, args):
            work = os.path.join(cls.work.name, server_name)
            os.mkdir(work)
            server = Locatord(LOCATORD, args, work)
            cls.servers.append(server)
            return server

        try:
            cls.shards = [start(f"shard{k}",
                                ["--dataset", dataset, "--tiles", f"{k}/2"])
                          for k in range(2)]
            cls.router = start("router", [
                "--route", "--shards",
                ",".join(shard.target for shard in cls.shards)])
            cls.whole = start("whole", ["--dataset", dataset])
        except Exception:
            cls.tearDownClass()
            raise

    @classmethod
    def tearDownClass(cls):
        for server in cls.servers:
            server.stop()
        cls.work.cleanup()


class RoutingE2eTest(TileSetServers):

    @classmethod
    def setUpClass(cls):
        cls.work = tempfile.TemporaryDirectory()
        tile_set = os.path.join(cls.work.name, "tiles")
        subprocess.run([LOCATOR_BUILD, "uniform:20000:1", "--out", tile_set,
                        "--tile-points", "2000", "--quiet"],
                       check=True, capture_output=True)
        cls.serve(tile_set, "big")

    def test_a_shards_own_topology_is_incomplete(self):
        from locator_client import LocatorClient, LocatorError
        with LocatorClient(self.shards[0].target, dataset="big",
                           route=True) as client:
            topology = client.topology()
            self.assertTrue(topology.tiled)
            self.assertFalse(topology.complete)
            self.assertEqual(len(topology.tiles), 10)
            (shard,) = topology.shards
            self.assertEqual(shard.target, "")
            missing = min(set(range(10)) - set(shard.tiles))
            for call in [lambda: client.locate(0.5, 0.5),
                         lambda: client.locate_batch([0.1, 0.9], [0.1, 0.1])]:
                with self.assertRaises(LocatorError) as raised:
                    call()
                self.assertEqual(raised.exception.code, "FAILED_PRECONDITION")
                self.assertEqual(
                    raised.exception.details,
                    f"topology of dataset 'big' is incomplete: tile {missing} "
                    "has no shard; route through a router (locatord --route)")

    def test_routed_through_the_routers_topology_as_the_whole_server(self):
        from locator_client import LocatorClient
        rng = random.Random(5)
        points = [(rng.random(), rng.random()) for _ in range(2000)]
        # Outside the bounds and the hull, on the bounds' corners, far off.
        points += [(-0.5, 0.5), (1.5, 0.5), (0.5, -0.25), (0.5, 1.25),
                   (-2, -2), (3, 3), (-1, 2), (2, -1), (0, 0), (1, 1),
                   (0, 1), (1, 0), (-1e9, 1e9), (1e300, -1e300)]
        rng.shuffle(points)
        xs, ys = [p[0] for p in points], [p[1] for p in points]
        with LocatorClient(self.router.target, dataset="big",
                           route=True) as routed, \
                LocatorClient(self.whole.target, dataset="big") as whole:
            topology = routed.topology()
            self.assertTrue(topology.complete)
            self.assertEqual([shard.target for shard in topology.shards],
                             [shard.target for shard in self.shards])
            self.router.stop()  # the topology is all the client needs
            for flags in [{}, {"vertex_ids": True, "barycentric": True,
                               "values": True}]:
                answers = routed.locate_batch(xs, ys, **flags)
                expected = whole.locate_batch(xs, ys, **flags)
                self.assertEqual(without_costs(answers),
                                 without_costs(expected))
            types = {answer.type for answer in answers}
            self.assertIn("FACE", types)
            self.assertIn("OUTSIDE_CONVEX_HULL", types)
            for x, y in points[:50]:
                self.assertEqual(without_costs([routed.locate(x, y)]),
                                 without_costs([whole.locate(x, y)]))


class CrsRoutingE2eTest(TileSetServers):
    """A tile set in UTM zone 33N (3,000 points in a 2 km square near 15°E
    49.6°N, tiles of 400 points) served by two shards behind a router and
    by one locatord whole: a routing client given lon/lat points sends
    each to its shard where PROJ puts it in UTM, and answers as the whole
    server does, refusals included."""

    @classmethod
    def setUpClass(cls):
        cls.work = tempfile.TemporaryDirectory()
        rng = random.Random(11)
        cls.utm = [(500000 + 2000 * rng.random(),
                    5500000 + 2000 * rng.random()) for _ in range(3000)]
        csv = os.path.join(cls.work.name, "utm.csv")
        with open(csv, "w") as out:
            out.write("x,y,h\n")
            for x, y in cls.utm:
                out.write(f"{x!r},{y!r},{100 + (x - 500000) / 40!r}\n")
        tile_set = os.path.join(cls.work.name, "tiles")
        subprocess.run([LOCATOR_BUILD,
                        f"ogr:{csv}?oo=X_POSSIBLE_NAMES=x&"
                        "oo=Y_POSSIBLE_NAMES=y&z=h&a_srs=EPSG:32633",
                        "--out", tile_set, "--tile-points", "400", "--quiet"],
                       check=True, capture_output=True)
        cls.serve(tile_set, "utm")

    def clients(self, crs):
        from locator_client import LocatorClient
        return (LocatorClient(self.router.target, deadline_s=30,
                              dataset="utm", crs=crs, route=True),
                LocatorClient(self.whole.target, deadline_s=30,
                              dataset="utm", crs=crs))

    def test_lon_lat_points_answer_as_the_whole_server(self):
        from pyproj import Transformer
        rng = random.Random(12)
        # Around the square and on its points (the tiles' vertices).
        utm = [(499900 + 2200 * rng.random(), 5499900 + 2200 * rng.random())
               for _ in range(1000)] + self.utm[::3]
        to_lon_lat = Transformer.from_crs("EPSG:32633", "EPSG:4326",
                                          always_xy=True)
        xs, ys = to_lon_lat.transform(*zip(*utm))
        routed, whole = self.clients("EPSG:4326")
        with routed, whole:
            self.assertIn("UTM zone 33N", routed.topology().crs)
            flags = {"vertex_ids": True, "barycentric": True, "values": True}
            answers = routed.locate_batch(xs, ys, **flags)
            self.assertEqual(places(answers),
                             places(whole.locate_batch(xs, ys, **flags)))
            types = {answer.type for answer in answers}
            self.assertTrue({"FACE", "VERTEX"} <= types, types)
            for x, y in list(zip(xs, ys))[::37]:
                self.assertEqual(
                    places([routed.locate(x, y)]),
                    places([whole.locate(x, y)]))

    def test_what_cannot_be_mapped_is_refused_as_the_whole_server_does(self):
        from locator_client import LocatorError
        # A point outside the CRS's area of use, an unknown CRS, one that
        # names a file.
        for crs, far in [("EPSG:4326", (170, -80)),
                         ("EPSG:999999", (15, 49.6)),
                         ("/etc/passwd", (15, 49.6))]:
            xs = [15.0 + 0.001 * i for i in range(20)]
            ys = [49.6] * 20
            xs[13], ys[13] = far
            routed, whole = self.clients(crs)
            with routed, whole:
                for call in (lambda client: client.locate_batch(xs, ys),
                             lambda client: client.locate(*far)):
                    with self.assertRaises(LocatorError) as got:
                        call(routed)
                    with self.assertRaises(LocatorError) as want:
                        call(whole)
                    self.assertEqual(got.exception.code, "INVALID_ARGUMENT")
                    self.assertEqual(got.exception.code, want.exception.code)
                    # In the shard's words, naming the shard.
                    self.assertRegex(got.exception.details,
                                     r"^shard 127\.0\.0\.1:\d+: ")
                    self.assertEqual(
                        got.exception.details.split(": ", 1)[1],
                        want.exception.details, crs)


def main():
    global LOCATORD, LOCATOR_BUILD, PYTHON_DIR
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    LOCATORD, LOCATOR_BUILD, PYTHON_DIR = sys.argv[1:]
    sys.path.insert(0, PYTHON_DIR)
    unittest.main(argv=sys.argv[:1], verbosity=2)


if __name__ == "__main__":
    main()
