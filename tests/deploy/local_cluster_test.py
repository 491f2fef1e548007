#!/usr/bin/env python3
"""ctest: deploy/local-cluster.sh, in a short run, loses no call.

Runs the script once (12 s of load through nginx; replica 2 SIGKILLed 3 s
in and restarted 3 s later) and checks the JSON summary it writes. Each
check is its own test method, so a failure names what broke.

Usage: local_cluster_test.py SCRIPT BUILD_DIR
"""

import json
import os
import pathlib
import subprocess
import sys
import tempfile
import unittest

SCRIPT = BUILD_DIR = None  # set from the command line in main()

# The short configuration: small enough to build in well under a second,
# long enough that the restart (at 6 s) has time to finish on a loaded
# machine before the load ends. Re-tuning every 200 queries, the victim has
# saved its tuning within a second even when ASAN slows every replica.
CLUSTER_ENV = {
    "DURATION": "12",
    "KILL_AT": "3",
    "RESTART_AFTER": "3",
    "DATASET": "uniform:20000:1",
    "WORKLOAD": "1-cluster",
    "CONCURRENCY": "8",
    "RETUNE_EVERY": "200",
}


class LocalClusterTest(unittest.TestCase):
    """Checks of one run of the script."""

    @classmethod
    def setUpClass(cls):
        with tempfile.TemporaryDirectory() as work:
            summary_path = os.path.join(work, "summary.json")
            env = dict(os.environ, BUILD_DIR=BUILD_DIR,
                       SUMMARY_JSON=summary_path, **CLUSTER_ENV)
            cls.run_result = subprocess.run(
                ["bash", SCRIPT], env=env, capture_output=True, text=True,
                timeout=240, check=False)
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

    def test_no_call_failed(self):
        self.assertEqual(self.summary["failed_calls"], 0,
                         self.summary["errors"])
        self.assertEqual(self.summary["load_exit_code"], 0)
        self.assertGreater(self.summary["calls"], 0)

    def test_calls_were_served_before_during_and_after_the_failure(self):
        phases = self.summary["phases"]
        self.assertEqual([p["name"] for p in phases],
                         ["before", "during", "after"])
        for phase in phases:
            self.assertGreater(phase["calls"], 0, phase)
            self.assertEqual(phase["failed_calls"], 0, phase)
            self.assertLessEqual(phase["p50_us"], phase["p99_us"], phase)

    def test_restarted_replica_came_back_tuned(self):
        restarted = self.summary["restarted"]
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
