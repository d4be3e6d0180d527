#!/usr/bin/env python3
"""Check that the worked examples of docs/contributing.md are the compiled files.

Usage: check_contributing_examples.py SOURCE_DIR

A fenced code block of docs/contributing.md that follows a line `<!-- file: PATH -->` must equal the
file PATH (relative to SOURCE_DIR) byte for byte; those files are compiled into test_contributing
(tests/contributing/) and run by ctest, so the examples the doc shows are code that builds and passes.
Exit 1 (and one line per problem) if a block differs from its file, a named file is missing, or no
block is marked at all.
"""
import pathlib
import re
import sys

MARK = re.compile(r"^<!-- file: (\S+) -->\n```[a-z]*\n(.*?)^```$", re.S | re.M)


def main():
    root = pathlib.Path(sys.argv[1])
    doc = (root / "docs" / "contributing.md").read_text()
    problems, blocks = [], MARK.findall(doc)
    if not blocks:
        problems.append("docs/contributing.md: no code block marked <!-- file: PATH -->")
    for path, code in blocks:
        f = root / path
        if not f.is_file():
            problems.append(f"docs/contributing.md: {path} does not exist")
        elif f.read_text() != code:
            problems.append(f"docs/contributing.md: the block of {path} differs from the file (copy the file in)")
    for p in problems:
        print(p)
    print(f"check_contributing_examples: {len(blocks)} blocks, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
