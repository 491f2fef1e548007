"""The documents a newcomer reads are true.

    docs_test.py links SOURCE_DIR
        Every relative link in README.md, docs/*.md and deploy/README.md
        names a file of the tree, and every #anchor a heading of the page it
        points to (GitHub's heading ids).
    docs_test.py quick-start SOURCE_DIR BUILD_DIR
        Runs the README's "Quick start" as written, in a scratch directory,
        with the programs of BUILD_DIR and locatord on a port the OS picked:
        the locate prints exactly the output the README shows, and the
        GeoTIFF it renders is what its comment says.
"""

import os
import re
import socket
import subprocess
import sys
import tempfile

LINK = re.compile(r"\[[^\]]*\]\(([^)\s]+)\)")
FENCE = re.compile(r"^```(\w*)\n(.*?)^```\n", re.MULTILINE | re.DOTALL)


def pages(source_dir):
    docs = os.path.join(source_dir, "docs")
    names = ["README.md", "deploy/README.md"]
    names += ["docs/" + n for n in sorted(os.listdir(docs)) if n.endswith(".md")]
    return [os.path.join(source_dir, n) for n in names]


def without_code(text):
    """`text` without fenced blocks and inline code, where brackets are code."""
    text = FENCE.sub("", text)
    return re.sub(r"`[^`\n]*`", "", text)


def anchors(path):
    """The ids GitHub gives the headings of the Markdown file `path`."""
    ids = set()
    seen = {}
    with open(path, encoding="utf-8") as page:
        text = FENCE.sub("", page.read())
    for heading in re.findall(r"^#+\s+(.*?)\s*#*$", text, re.MULTILINE):
        slug = heading.strip().lower()
        slug = re.sub(r"[^\w\- ]", "", slug).replace(" ", "-")
        count = seen.get(slug, 0)
        seen[slug] = count + 1
        ids.add(slug if count == 0 else "%s-%d" % (slug, count))
    return ids


def check_links(source_dir):
    broken = []
    for page in pages(source_dir):
        with open(page, encoding="utf-8") as f:
            text = without_code(f.read())
        shown = os.path.relpath(page, source_dir)
        for target in LINK.findall(text):
            if re.match(r"^[a-z]+:", target):
                continue  # http:, https:, mailto:
            path, _, anchor = target.partition("#")
            resolved = os.path.normpath(
                os.path.join(os.path.dirname(page), path)) if path else page
            if not os.path.exists(resolved):
                broken.append("%s: %s: no such file" % (shown, target))
            elif anchor and resolved.endswith(".md") and (
                    anchor not in anchors(resolved)):
                broken.append("%s: %s: no heading with this id" %
                              (shown, target))
    for line in broken:
        print(line)
    print("%d broken links" % len(broken))
    return 1 if broken else 0


def quick_start_blocks(readme):
    """The fenced blocks of the README's "Quick start" section, in order,
    as (language, text)."""
    with open(readme, encoding="utf-8") as f:
        text = f.read()
    section = re.search(r"^## Quick start.*?\n(.*?)(?=^## )", text,
                        re.MULTILINE | re.DOTALL)
    assert section, "README.md has no '## Quick start' section"
    return FENCE.findall(section.group(1))


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def as_test_script(block, build_dir, port):
    """The README's shell block with the build tree's programs, locatord on
    `port` until the script ends, and the clients waiting until it serves."""
    target = "127.0.0.1:%d" % port
    block = block.replace("build/", build_dir + "/")
    block = block.replace("127.0.0.1:50051", target)
    block = re.sub(r"(/client/locator)\b(?!-)", r"\1 --target " + target,
                   block)
    wait = ("SERVER=$!\ntrap 'kill $SERVER' EXIT\n"
            "for i in $(seq 600); do\n"
            "  %s/client/locator --target %s health > /dev/null 2>&1 && break\n"
            "  sleep 0.1\n"
            "done\n" % (build_dir, target))
    block = re.sub(r"&\s*$", "> locatord.log 2>&1 &\n" + wait, block,
                   flags=re.MULTILINE)
    return "set -euo pipefail\n" + block


def check_quick_start(source_dir, build_dir):
    blocks = quick_start_blocks(os.path.join(source_dir, "README.md"))
    # A shell block, the output its last command prints, then a shell block
    # whose comments say what its last command shows.
    (lang1, serve), (lang2, shown), (lang3, render) = blocks[:3]
    assert (lang1, lang2, lang3) == ("sh", "", "sh"), blocks
    port = free_port()
    with tempfile.TemporaryDirectory() as work:
        script = as_test_script(serve + render, build_dir, port)
        run = subprocess.run(["bash", "-c", script], cwd=work, text=True,
                             capture_output=True, timeout=600)
        log = os.path.join(work, "locatord.log")
        if run.returncode != 0:
            print(run.stdout, run.stderr)
            if os.path.exists(log):
                print(open(log).read())
            return 1
    failures = []
    if shown not in run.stdout:
        failures.append("the locate printed other than the README shows:\n"
                        "--- README\n%s--- printed\n%s" % (shown, run.stdout))
    for claim in ("Size is 40, 40", "UTM zone 33N", "NoData Value=-9999"):
        if claim not in run.stdout:
            failures.append("gdalinfo does not say %r:\n%s" %
                            (claim, run.stdout))
    for failure in failures:
        print(failure)
    return 1 if failures else 0


def main(argv):
    if len(argv) == 3 and argv[1] == "links":
        return check_links(argv[2])
    if len(argv) == 4 and argv[1] == "quick-start":
        return check_quick_start(argv[2], argv[3])
    print(__doc__)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv))
