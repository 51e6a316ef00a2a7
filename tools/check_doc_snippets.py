#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Checks that the code blocks of a Markdown file are the files they quote.

A block is quoted with a comment on the line before its fence:
    <!-- snippet: examples/library/CMakeLists.txt -->        the whole file
    <!-- snippet: examples/library/torus_hits.cpp:12-47 -->  lines 12 to 47
Paths are relative to the repository. Prints each block that differs, with
the first differing line, and exits 1; exits 0 when all match.

    tools/check_doc_snippets.py docs/library.md [MORE.md ...]
"""
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
MARK = re.compile(r"^<!-- snippet: (?P<path>[^:\s]+)(?::(?P<first>\d+)-(?P<last>\d+))? -->$")


def blocks(lines):
    """(line number of the mark, path, first, last, block lines) for each quoted block."""
    for i, line in enumerate(lines):
        m = MARK.match(line.strip())
        if not m:
            continue
        if i + 1 >= len(lines) or not lines[i + 1].startswith("```"):
            yield i + 1, m["path"], None, None, None
            continue
        end = next((j for j in range(i + 2, len(lines)) if lines[j].startswith("```")), None)
        body = lines[i + 2:end] if end is not None else None
        first = int(m["first"]) if m["first"] else None
        last = int(m["last"]) if m["last"] else None
        yield i + 1, m["path"], first, last, body


def check(doc):
    lines = doc.read_text().splitlines()
    problems = 0
    count = 0
    for where, path, first, last, body in blocks(lines):
        count += 1
        name = f"{doc}:{where}"
        if body is None:
            print(f"{name}: the snippet mark for {path} is not followed by a closed code block")
            problems += 1
            continue
        source = ROOT / path
        if not source.is_file():
            print(f"{name}: {path} does not exist")
            problems += 1
            continue
        text = source.read_text().splitlines()
        if first is not None:
            if not (1 <= first <= last <= len(text)):
                print(f"{name}: lines {first}-{last} are not in {path} ({len(text)} lines)")
                problems += 1
                continue
            text = text[first - 1:last]
        if body != text:
            k = next((k for k in range(max(len(body), len(text)))
                      if k >= len(body) or k >= len(text) or body[k] != text[k]))
            got = body[k] if k < len(body) else "(end of block)"
            want = text[k] if k < len(text) else "(end of file)"
            print(f"{name}: the block differs from {path} at its line {k + 1}:\n  doc:  {got}\n  file: {want}")
            problems += 1
    if count == 0:
        print(f"{doc}: no snippet marks")
        problems += 1
    return problems, count


def main(argv):
    if len(argv) < 2:
        print(__doc__.strip())
        return 2
    total = 0
    quoted = 0
    for arg in argv[1:]:
        problems, count = check(pathlib.Path(arg))
        total += problems
        quoted += count
    if total == 0:
        print(f"snippets: ok ({quoted} blocks)")
    return 1 if total else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
