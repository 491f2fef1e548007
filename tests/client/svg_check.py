#!/usr/bin/env python3
"""Checks that an SVG file is well-formed XML and summarizes it as JSON.

Usage: svg_check.py FILE.svg

Prints one JSON object: root (the root tag without namespace), polylines
(the number of points of each polyline, in document order), dashed_lines
(lines with a stroke-dasharray) and texts (every text element's content).
Exits 1, with the parser's message on stderr, when the file is not
well-formed XML. The C++ tests of the SVG writer and of locator-load --plot
run it, so that XML validity is judged by a real parser.
"""

import json
import sys
import xml.etree.ElementTree as ElementTree

SVG = "{http://www.w3.org/2000/svg}"


def summarize(root):
    """The JSON-ready summary of the SVG element tree under `root`."""
    return {
        "root": root.tag.removeprefix(SVG),
        "polylines": [
            len(p.get("points", "").split())
            for p in root.iter(SVG + "polyline")
        ],
        "dashed_lines": sum(
            "stroke-dasharray" in line.get("style", "")
            for line in root.iter(SVG + "line")
        ),
        "texts": [t.text or "" for t in root.iter(SVG + "text")],
    }


def main(argv):
    if len(argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    try:
        root = ElementTree.parse(argv[1]).getroot()
    except ElementTree.ParseError as error:
        print(f"not well-formed XML: {error}", file=sys.stderr)
        return 1
    print(json.dumps(summarize(root)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
