#!/usr/bin/env python3
"""ctest: deploy/local-cluster.sh --shards 4 --replicas 2 loses no call.

Runs the sharded cluster once in a short run: a tile set of 20,000 points
in 20 tiles, 8 s of load against one locatord serving all of it, then 8 s
through nginx, 2 routers and 4 shards of 2 replicas (replica 0 of shard 1
SIGKILLed 2 s in and restarted 2 s later). It checks the JSON summary the
script writes. Each check is its own test method, so a failure names what
broke.

Usage: local_cluster_shards_test.py SCRIPT BUILD_DIR
"""

import json
import os
import pathlib
import subprocess
import sys
import tempfile
import unittest

SCRIPT = BUILD_DIR = None  # set from the command line in main()

SHARDS, REPLICAS = 4, 2
# Small and short: every process maps the tile set at once, and the
# restart (at 4 s) finishes well before the load ends even under ASAN.
# Re-tuning every 200 queries, the victim (an eighth of the calls) has
# saved its tuning within a second.
CLUSTER_ENV = {
    "DURATION": "8",
    "KILL_AT": "2",
    "RESTART_AFTER": "2",
    "DATASET": "uniform:20000:1",
    "WORKLOAD": "uniform",
    "CONCURRENCY": "8",
    "RETUNE_EVERY": "200",
}


class LocalClusterShardsTest(unittest.TestCase):
    """Checks of one run of the script with --shards."""

    @classmethod
    def setUpClass(cls):
        with tempfile.TemporaryDirectory() as work:
            summary_path = os.path.join(work, "summary.json")
            env = dict(os.environ, BUILD_DIR=BUILD_DIR,
                       SUMMARY_JSON=summary_path, **CLUSTER_ENV)
            cls.run_result = subprocess.run(
                ["bash", SCRIPT, "--shards", str(SHARDS),
                 "--replicas", str(REPLICAS)],
                env=env, capture_output=True, text=True, timeout=240,
                check=False)
            print(cls.run_result.stdout, cls.run_result.stderr,
                  file=sys.stderr)
            summary = pathlib.Path(summary_path)
            cls.summary = (json.loads(summary.read_text())
                           if summary.exists() else None)

    def setUp(self):
        self.assertIsNotNone(self.summary, "the script wrote no summary")

    def test_script_exits_zero(self):
        self.assertEqual(self.run_result.returncode, 0,
                         self.run_result.stderr)

    def test_the_cluster_was_sharded(self):
        sharded = self.summary["sharded"]
        self.assertEqual(sharded["shards"], SHARDS)
        self.assertEqual(sharded["replicas_per_shard"], REPLICAS)
        self.assertGreaterEqual(sharded["tiles"], SHARDS)

    def test_no_call_failed(self):
        self.assertEqual(self.summary["failed_calls"], 0,
                         self.summary["errors"])
        self.assertEqual(self.summary["load_exit_code"], 0)
        self.assertGreater(self.summary["calls"], 0)
        self.assertEqual(self.summary["failed_calls_during_kill"], 0)

    def test_calls_were_served_before_during_and_after_the_failure(self):
        phases = self.summary["phases"]
        self.assertEqual([p["name"] for p in phases],
                         ["before", "during", "after"])
        for phase in phases:
            self.assertGreater(phase["calls"], 0, phase)
            self.assertEqual(phase["failed_calls"], 0, phase)

    def test_both_throughputs_and_their_ratio_are_reported(self):
        throughput = self.summary["throughput"]
        self.assertEqual(throughput["one_box_failed_calls"], 0,
                         throughput["one_box_errors"])
        self.assertEqual(throughput["one_box_exit_code"], 0)
        self.assertGreater(throughput["one_box_calls_per_second"], 0)
        self.assertGreater(throughput["cluster_calls_per_second"], 0)
        self.assertAlmostEqual(
            throughput["cluster_to_one_box"],
            throughput["cluster_calls_per_second"] /
            throughput["one_box_calls_per_second"])
        self.assertIn("throughput  one box", self.run_result.stdout)

    def test_restarted_replica_came_back_tuned(self):
        restarted = self.summary["restarted"]
        self.assertEqual((restarted["shard"], restarted["replica"]), (1, 0))
        # None means the first GetStats came after the replica could have
        # re-tuned by itself; that proves nothing either way.
        self.assertIs(restarted["tuned_at_restart"], True, restarted)


def main():
    global SCRIPT, BUILD_DIR
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    SCRIPT, BUILD_DIR = sys.argv[1], sys.argv[2]
    unittest.main(argv=sys.argv[:1], verbosity=2)


if __name__ == "__main__":
    main()
