#!/usr/bin/env python3
"""Lint: the repository must be self-contained.

Fails (exit 1, one `file:line: message` per finding) on
  * references to anything outside the repository in tracked text files: the physics
    specification or paper files kept beside the project, relative paths that climb out of the
    repository into a sibling folder, absolute paths of the development machines;
  * dead links: relative markdown links and inline/fenced code paths that name a repository file
    (`docs/<page>.md`, `scripts/x.sh`, `cases/x.toml`, ...) in the markdown pages, and any `docs/<page>.md`
    named anywhere in a tracked text file, that do not exist.

Usage: check_refs.py [--root DIR]      check DIR (default: the repository holding this script)
       check_refs.py --self-test       feed the checker a bad and a good tree, check it tells them apart
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

# Outside references. Each pattern is written so that this file does not match itself.
OUTSIDE = [
    (re.compile(r"\.\./+shared\b"), "path into a folder beside the repository"),
    (re.compile(r"\bshared/(?:seeds|reference|M[O]DEL)"), "path into the shared project folder"),
    (re.compile(r"\bM[O]DEL\b"), "the external physics specification; cite docs/model.md and its section"),
    (re.compile(r"\bseeds/"), "path into the external paper folder"),
    (re.compile(r"\b\d{3}_[0-9a-f]{16}[.]txt\b"), "external paper file; cite the paper instead"),
    (re.compile(r"(?<![\w.])/wo[r]k/"), "absolute path of the development machine"),
    (re.compile(r"(?<![\w.])/(?:home|Users)/[A-Za-z_][\w.-]*"), "absolute home path"),
    (re.compile(r"(?<![\w.])/ro[o]t/"), "absolute home path"),
]

TOP = r"(?:docs|scripts|src|apps|tests|cases|bench|\.ci)"
# A repository path inside code: starts at a top-level folder, made of plain path characters.
CODE_PATH = re.compile(r"(?<![\w./-])(" + TOP + r"/[\w.+*?<>{}$-]+(?:/[\w.+*?<>{}$-]+)*/?)")
DOCS_PAGE = re.compile(r"(?<![\w./-])(docs/[\w.-]+[.]md)\b")
MD_LINK = re.compile(r"!?\[[^\]]*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
INLINE_CODE = re.compile(r"`([^`\n]+)`")
SKIP_DIRS = {".git", "results", "__pycache__"}
BINARY_EXT = {".png", ".jpg", ".jpeg", ".gif", ".pdf", ".vtp", ".vtu", ".pvd", ".gz", ".zip", ".ico"}


def tracked_files(root):
    """Tracked files (git ls-files), or every file below root outside build folders without git."""
    try:
        out = subprocess.run(["git", "-C", root, "ls-files", "-z"], capture_output=True, check=True)
        files = [f for f in out.stdout.decode().split("\0") if f]
        if files:
            return sorted(f for f in files if os.path.isfile(os.path.join(root, f)))
    except (OSError, subprocess.CalledProcessError):
        pass
    files = []
    for d, dirs, names in os.walk(root):
        dirs[:] = [x for x in dirs if x not in SKIP_DIRS and not x.startswith("build")]
        files += [os.path.relpath(os.path.join(d, n), root) for n in names]
    return sorted(files)


def read_text(path):
    if os.path.splitext(path)[1].lower() in BINARY_EXT:
        return None
    with open(path, "rb") as f:
        data = f.read()
    if b"\0" in data[:8192]:
        return None
    return data.decode("utf-8", errors="replace")


def exists(root, rel):
    rel = rel.rstrip(".,;:")
    if any(c in rel for c in "*?<>{}$"):
        return True  # a pattern or placeholder, not a file name
    return os.path.exists(os.path.join(root, rel))


def code_paths(line, in_fence):
    """Repository paths named in code on this line (inline spans, or the whole line in a fence)."""
    spans = [line] if in_fence else INLINE_CODE.findall(line)
    for span in spans:
        for m in CODE_PATH.finditer(span):
            yield m.group(1)


def check_markdown(root, rel, lines, report):
    base = os.path.dirname(rel)
    in_fence = False
    for n, line in enumerate(lines, 1):
        if line.lstrip().startswith("```"):
            in_fence = not in_fence
            continue
        if not in_fence:
            for m in MD_LINK.finditer(line):
                target = m.group(1).split("#", 1)[0]
                if not target or re.match(r"^[a-z][a-z0-9+.-]*:", target):
                    continue  # anchor only, or a URL (http:, mailto:, ...)
                full = os.path.normpath(os.path.join(base, target))
                if full.startswith(".."):
                    report(rel, n, f"link leaves the repository: {target}")
                elif not os.path.exists(os.path.join(root, full)):
                    report(rel, n, f"dead link: {target}")
        for p in code_paths(line, in_fence):
            if not DOCS_PAGE.fullmatch(p) and not exists(root, p):  # pages: checked for every file
                report(rel, n, f"names a repository path that does not exist: {p}")


def check(root, out=sys.stdout):
    """Prints every finding as file:line: message; returns their number."""
    findings = set()

    def report(rel, n, msg):
        findings.add((rel, n, msg))

    for rel in tracked_files(root):
        text = read_text(os.path.join(root, rel))
        if text is None:
            continue
        lines = text.splitlines()
        for n, line in enumerate(lines, 1):
            for pat, why in OUTSIDE:  # the first kind found on a line is enough
                m = pat.search(line)
                if m:
                    report(rel, n, f"refers outside the repository ({why}): {m.group(0)}")
                    break
            for m in DOCS_PAGE.finditer(line):
                if not exists(root, m.group(1)):
                    report(rel, n, f"names a documentation page that does not exist: {m.group(1)}")
        if rel.endswith(".md"):
            check_markdown(root, rel, lines, report)
    for rel, n, msg in sorted(findings):
        print(f"{rel}:{n}: {msg}", file=out)
    return len(findings)


def write(root, rel, text):
    path = os.path.join(root, rel)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)


def self_test():
    """A tree with one file per kind of defect must fail with each defect reported; a clean tree passes."""
    import io
    # "~" is removed before use, so that this file itself holds none of the defects it plants.
    bad = {
        "docs/~a.md": "See [spec](../../sha~red/MO~DEL.md) and [b](b.md).\n",
        "docs/~b.md": "Run `scripts/~missing.sh` or see `docs/~gone.md`.\n```\nbuild/agglo vcrit cases/~none.toml\n```\n",
        "cases/x.toml": "# MO~DEL C.6 decision, see docs/~charged.md\nkey = 1\n",
        "src/y.hpp": "// data in /wo~rk/data\n// text of 000_4b7c5452647d356b~.txt\n// ../sha~red/reference/x.csv\n",
        "README.md": "![img](docs/img/~none.png) and [home](/ho~me/user/x)\n",
    }
    expected = [
        ("docs/~a.md", 1, "outside"), ("docs/~b.md", 1, "scripts/~missing.sh"), ("docs/~b.md", 1, "docs/~gone.md"),
        ("docs/~b.md", 3, "cases/~none.toml"), ("cases/x.toml", 1, "outside"), ("cases/x.toml", 1, "docs/~charged.md"),
        ("src/y.hpp", 1, "/wo~rk/"), ("src/y.hpp", 2, "~.txt"), ("src/y.hpp", 3, "../sha~red"),
        ("README.md", 1, "dead link: docs/img/~none.png"), ("README.md", 1, "home"),
    ]
    bad = {rel.replace("~", ""): text.replace("~", "") for rel, text in bad.items()}
    expected = [(rel.replace("~", ""), line, needle.replace("~", "")) for rel, line, needle in expected]
    good = {
        "docs/model.md": "# Model\n## A.2 Contact\nSee [dem](dem.md#model), `docs/dem.md`, `scripts/run.sh` and "
                         "[paper](https://doi.org/10.1000/x).\n```\nagglo collide cases/ok.toml --out results/x\n```\n",
        "docs/dem.md": "docs/model.md §A.2; files under `tests/cli/*.sh`, `case_NN_<value>/`.\n",
        "scripts/run.sh": "#!/bin/sh\n",
        "cases/ok.toml": "# docs/model.md §C.6\nkey = 1\n",
        "README.md": "[model](docs/model.md) [top](#top)\n",
    }
    ok = True
    with tempfile.TemporaryDirectory() as d:
        for rel, text in bad.items():
            write(d, rel, text)
        buf = io.StringIO()
        n = check(d, buf)
        got = buf.getvalue()
        for rel, line, needle in expected:
            hit = [x for x in got.splitlines() if x.startswith(f"{rel}:{line}:") and needle in x]
            if not hit:
                print(f"self-test: missed {rel}:{line} ({needle})")
                ok = False
        if not ok or n == 0:
            print(f"self-test: findings in the bad tree were:\n{got}")
            ok = False
    with tempfile.TemporaryDirectory() as d:
        for rel, text in good.items():
            write(d, rel, text)
        buf = io.StringIO()
        if check(d, buf) != 0:
            print(f"self-test: false findings in a clean tree:\n{buf.getvalue()}")
            ok = False
    print("self-test passed" if ok else "self-test FAILED")
    return 0 if ok else 1


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--root", default=os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    ap.add_argument("--self-test", action="store_true")
    a = ap.parse_args()
    if a.self_test:
        return self_test()
    n = check(os.path.abspath(a.root))
    if n:
        print(f"check_refs: {n} finding(s): references outside the repository or dead links", file=sys.stderr)
        return 1
    print("check_refs: no references outside the repository, no dead links")
    return 0


if __name__ == "__main__":
    sys.exit(main())
