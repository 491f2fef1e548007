#!/usr/bin/env python3
"""Locates the points of a CSV file with LocateBatch and prints, for each,
its triangle and the dataset's z interpolated there.

usage: locate_csv.py [--target HOST:PORT] [--deadline-s S] [--chunk N]
                     [--retry] POINTS.csv

POINTS.csv has "x,y" per line; blank lines and lines starting with '#' are
skipped, and a first line that is not numbers is taken for a header. The
output is CSV with a header: x,y,type,triangle_id,v0,v1,v2,z (z is empty
where the dataset has no values or the point is outside the hull). Points
go to the server in batches of --chunk.

Exit codes: 0 ok; 1 a call failed (printed as "error: CODE: message");
2 usage or an unreadable file.

Run it with the build's stubs on the path, e.g.
    PYTHONPATH=build/python python3 client/python/examples/locate_csv.py \\
        --target 127.0.0.1:50051 points.csv
"""

import argparse
import csv
import sys

from locator_client import LocatorClient, LocatorError

EXIT_CALL_FAILED = 1
EXIT_USAGE = 2


class InputError(Exception):
    """The points file cannot be read or parsed."""


def read_points(path):
    """Yields (line_number, x, y) for every point row of the file."""
    first = True
    try:
        with open(path, newline="") as points:
            for number, row in enumerate(csv.reader(points), start=1):
                if not "".join(row).strip() or row[0].lstrip().startswith("#"):
                    continue
                try:
                    if len(row) != 2:
                        raise ValueError
                    x, y = float(row[0]), float(row[1])
                except ValueError:
                    if first:  # a header
                        first = False
                        continue
                    raise InputError(f"{path}:{number}: expected x,y, got "
                                     f"{','.join(row)!r}") from None
                first = False
                yield number, x, y
    except OSError as error:
        raise InputError(f"{path}: {error.strerror}") from None


def chunks(rows, size):
    """Groups `rows` into lists of at most `size`."""
    chunk = []
    for row in rows:
        chunk.append(row)
        if len(chunk) == size:
            yield chunk
            chunk = []
    if chunk:
        yield chunk


def format_row(x, y, answer):
    """One output line; repr() prints floats exactly (shortest round trip)."""
    corners = list(answer.vertex_ids) or ["", "", ""]
    z = "" if answer.value is None else repr(answer.value)
    return ",".join([repr(x), repr(y), answer.type, str(answer.triangle_id),
                     *map(str, corners), z])


def main(argv):
    parser = argparse.ArgumentParser(
        description="Locate the points of a CSV file with LocateBatch.")
    parser.add_argument("points", help="CSV file of x,y rows")
    parser.add_argument("--target", default="127.0.0.1:50051",
                        help="server HOST:PORT (default %(default)s)")
    parser.add_argument("--deadline-s", type=float, default=10.0,
                        help="deadline of each call (default %(default)s)")
    parser.add_argument("--chunk", type=int, default=10000,
                        help="points per LocateBatch (default %(default)s)")
    parser.add_argument("--retry", action="store_true",
                        help="retry calls that fail with UNAVAILABLE")
    args = parser.parse_args(argv)
    if args.chunk <= 0:
        parser.error("--chunk must be positive")

    print("x,y,type,triangle_id,v0,v1,v2,z")
    with LocatorClient(args.target, deadline_s=args.deadline_s,
                       retry_unavailable=args.retry) as client:
        try:
            for chunk in chunks(read_points(args.points), args.chunk):
                xs = [x for _, x, _ in chunk]
                ys = [y for _, _, y in chunk]
                try:
                    answers = client.locate_batch(xs, ys, vertex_ids=True,
                                                  values=True)
                except LocatorError as error:
                    # The server counts points from 0 within the batch.
                    print(f"error: {error} (in the batch of {len(chunk)} "
                          f"points from line {chunk[0][0]} of "
                          f"{args.points})", file=sys.stderr)
                    return EXIT_CALL_FAILED
                for x, y, answer in zip(xs, ys, answers):
                    print(format_row(x, y, answer))
        except InputError as error:
            print(f"error: {error}", file=sys.stderr)
            return EXIT_USAGE
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
