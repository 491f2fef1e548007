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


class RoutingE2eTest(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        cls.work = tempfile.TemporaryDirectory()
        tile_set = os.path.join(cls.work.name, "tiles")
        subprocess.run([LOCATOR_BUILD, "uniform:20000:1", "--out", tile_set,
                        "--tile-points", "2000", "--quiet"],
                       check=True, capture_output=True)
        dataset = "big=" + os.path.join(tile_set, "manifest.json")
        cls.servers = []

        def start(name, args):
            work = os.path.join(cls.work.name, name)
            os.mkdir(work)  # one log each
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


def main():
    global LOCATORD, LOCATOR_BUILD, PYTHON_DIR
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    LOCATORD, LOCATOR_BUILD, PYTHON_DIR = sys.argv[1:]
    sys.path.insert(0, PYTHON_DIR)
    unittest.main(argv=sys.argv[:1], verbosity=2)


if __name__ == "__main__":
    main()
