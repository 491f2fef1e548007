"""locatord as a child process of a Python test, on a port the OS picks.

    server = Locatord(LOCATORD, ["--dataset", path], work_dir)
    ... LocatorClient(server.target) ...
    server.stop()

The constructor returns once locatord listens and its default dataset
serves (GetStats answers); RuntimeError with its log if it does not within
STARTUP_SECONDS. Needs locator_client importable (PYTHON_DIR on sys.path).
"""

import os
import pathlib
import re
import subprocess
import time

STARTUP_SECONDS = 60


class Locatord:
    """locatord with `args` plus --listen 127.0.0.1:0, logging to a file in
    `work_dir`."""

    def __init__(self, locatord, args, work_dir):
        self.log = os.path.join(work_dir, "locatord.log")
        with open(self.log, "w") as log:
            self.process = subprocess.Popen(
                [locatord, *args, "--listen", "127.0.0.1:0"], stdout=log,
                stderr=subprocess.STDOUT)
        self.target = self._wait_for_listening()
        self._wait_until_serving()

    def _wait_for_listening(self):
        deadline = time.monotonic() + STARTUP_SECONDS
        while time.monotonic() < deadline:
            found = re.search(r"^locatord listening on (\S+)$",
                              self._log_text(), re.MULTILINE)
            if found:
                return found.group(1)
            if self.process.poll() is not None:
                break
            time.sleep(0.05)
        raise RuntimeError("locatord did not start:\n" + self._log_text())

    def _log_text(self):
        return pathlib.Path(self.log).read_text()

    def _wait_until_serving(self):
        from locator_client import LocatorClient, LocatorError
        deadline = time.monotonic() + STARTUP_SECONDS
        with LocatorClient(self.target, deadline_s=1) as client:
            while True:
                try:
                    client.stats()
                    return
                except LocatorError:
                    if time.monotonic() > deadline:
                        raise
                    time.sleep(0.05)

    def stop(self):
        self.process.terminate()
        self.process.wait(timeout=30)
