#!/usr/bin/env python3
"""Checks the shape of the tree (run by ctest as `layout_rules` and `layout_sizes`).

  check_layout.py rules   the library (include/) holds algorithms only, and nothing outside a
                          package includes that package's internal/ headers
  check_layout.py sizes   no file of include/, support/ or src/ over FILE_LIMIT lines, no library
                          function over FUNCTION_LIMIT lines, except the ones listed in scripts/size_exceptions.txt
                          at no more than their recorded size (the list may only shrink); prints
                          the largest files and functions
  check_layout.py sizes --update   rewrites scripts/size_exceptions.txt from the tree

Exit status 0 when the tree follows the rules, 1 otherwise (each breach on its own line).
"""

import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FILE_LIMIT = 700
FUNCTION_LIMIT = 100
EXCEPTIONS = os.path.join(ROOT, "scripts", "size_exceptions.txt")
PACKAGES = ["Consistent_segmentation", "Point_set_object_recognition", "Randomized_cuts",
            "Surface_mesh_symmetrization"]
CORE = "Shape_analysis"
SOURCE_SUFFIXES = (".h", ".hpp", ".cpp")
# Benchmarks whose subject is a package's private machinery itself (the own spatial indexes
# against CGAL's, which decides whether each one stays).
INTERNAL_BENCHMARKS = {os.path.join("bench", "spatial_indexes.cpp")}
INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]([^>"]+)[>"]', re.M)


def files_under(directory):
    out = []
    for base, dirs, names in os.walk(os.path.join(ROOT, directory)):
        dirs.sort()
        for name in sorted(names):
            if name.endswith(SOURCE_SUFFIXES):
                out.append(os.path.relpath(os.path.join(base, name), ROOT))
    return out


def read(path):
    with open(os.path.join(ROOT, path), encoding="utf-8", errors="replace") as f:
        return f.read()


def check_rules():
    breaches = []
    # The installed headers: algorithms and their types, nothing of the tool, tests or reports.
    for path in files_under("include"):
        for header in INCLUDE.findall(read(path)):
            if header.startswith(("Shape_analysis_support/", "nlohmann/", "CLI/", "gtest/")):
                breaches.append(f"{path}: the library includes <{header}>, which is not installed")
    # internal/ headers: a package's own, the Core's for the packages, support, tests and benchmarks.
    for directory in ["src", "examples", "support", "test", "bench"]:
        for path in files_under(directory):
            for header in INCLUDE.findall(read(path)):
                m = re.match(r"CGAL/(\w+)/internal/", header)
                if not m:
                    continue
                owner = m.group(1)
                if owner == CORE and directory in ("support", "test", "bench"):
                    continue  # the shared machinery, tested and benchmarked on its own
                if owner in PACKAGES and path.startswith(os.path.join("test", owner) + os.sep):
                    continue  # a package's tests may test its machinery
                if path in INTERNAL_BENCHMARKS:
                    continue
                breaches.append(f"{path}: includes <{header}>, internal to {owner}")
    for path in files_under("include"):
        m = re.match(r"include/CGAL/(\w+)/", path)
        for header in INCLUDE.findall(read(path)):
            h = re.match(r"CGAL/(\w+)/internal/", header)
            if h and m and h.group(1) in PACKAGES and h.group(1) != m.group(1):
                breaches.append(f"{path}: includes <{header}>, internal to {h.group(1)}")
    return breaches


def strip_comments_and_strings(text):
    """The text with comments, string and character literals blanked (newlines kept)."""
    out = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append("\n" * text.count("\n", i, j))
            i = j
        elif c in "\"'":
            if c == "'" and i > 0 and text[i - 1].isalnum():  # digit separator 1'000
                out.append(" ")
                i += 1
                continue
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            out.append(" ")
            i = j + 1
        else:
            out.append(c)
            i += 1
    return "".join(out)


SIGNATURE = re.compile(r"(~?[A-Za-z_]\w*(?:\s*::\s*~?[A-Za-z_]\w*)*|operator\s*[^\s(]+)\s*\([^;{}]*\)"
                       r"[^;{}()]*$", re.S)
NOT_FUNCTIONS = {"if", "for", "while", "switch", "catch", "return", "sizeof", "decltype", "alignof",
                 "static_assert", "defined", "throw"}


def functions(text):
    """(name, first line, number of lines) of every function body in a C++ text."""
    clean = strip_comments_and_strings(text)
    clean = re.sub(r"^\s*#.*$", "", clean, flags=re.M)  # preprocessor lines
    result = []
    stack = []  # per open brace: function name or None
    start = 0   # where the text before the next brace starts
    parens = 0  # depth of parentheses: braces inside them are initializers (default arguments)
    line = 1
    for i, c in enumerate(clean):
        if c == "\n":
            line += 1
        elif c == "(":
            parens += 1
        elif c == ")":
            parens = max(0, parens - 1)
        elif c == "{":
            name = None
            if parens == 0:
                before = clean[start:i]
                while True:  # drop brace initializers of default arguments: f(V v = {{0, 0}}) {
                    shorter = re.sub(r"\{[^{}]*\}", "", before)
                    if shorter == before:
                        break
                    before = shorter
                m = SIGNATURE.search(before.rstrip())
                if m:
                    candidate = re.sub(r"\s+", "", m.group(1))
                    if candidate.split("::")[-1] not in NOT_FUNCTIONS and not re.search(r"\]\s*$", before[:m.start()]):
                        name = candidate
                start = i + 1
            stack.append((name, line))
        elif c == "}":
            if stack:
                name, first = stack.pop()
                if name is not None:
                    result.append((name, first, line - first + 1))
            if parens == 0:
                start = i + 1
        elif c == ";" and parens == 0:
            start = i + 1
    return result


def measure():
    files, funcs = {}, {}
    # Files of the library, the support code and the tool; functions of the library.
    for path in files_under("include") + files_under("support") + files_under("src"):
        text = read(path)
        files[path] = text.count("\n") + (0 if text.endswith("\n") else 1)
        if not path.startswith("include"):
            continue
        for name, first, length in functions(text):
            key = f"{path}:{name}"
            funcs[key] = max(funcs.get(key, 0), length)
    return files, funcs


def load_exceptions():
    allowed = {}
    if os.path.exists(EXCEPTIONS):
        with open(EXCEPTIONS, encoding="utf-8") as f:
            for raw in f:
                entry = raw.split("#", 1)[0].strip()
                if entry:
                    key, size = entry.rsplit(None, 1)
                    allowed[key] = int(size)
    return allowed


def check_sizes(update):
    files, funcs = measure()
    over = {k: v for k, v in files.items() if v > FILE_LIMIT}
    over.update({k: v for k, v in funcs.items() if v > FUNCTION_LIMIT})
    print(f"largest files of include/, support/ and src/ (limit {FILE_LIMIT} lines):")
    for path, size in sorted(files.items(), key=lambda kv: -kv[1])[:8]:
        print(f"  {size:5d}  {path}")
    print(f"longest functions in them (limit {FUNCTION_LIMIT} lines):")
    for key, size in sorted(funcs.items(), key=lambda kv: -kv[1])[:12]:
        print(f"  {size:5d}  {key}")
    if update:
        with open(EXCEPTIONS, "w", encoding="utf-8") as f:
            f.write("# Library headers and functions over the limits of scripts/check_layout.py, at\n"
                    "# their size when listed: each may shrink (then lower or drop its line), none may\n"
                    "# grow, and nothing may be added. Cut them along their seams until this is empty.\n")
            for key in sorted(over):
                f.write(f"{key} {over[key]}\n")
        print(f"wrote {len(over)} exceptions to {os.path.relpath(EXCEPTIONS, ROOT)}")
        return []
    allowed = load_exceptions()
    breaches = []
    for key, size in sorted(over.items()):
        limit = FILE_LIMIT if key in files else FUNCTION_LIMIT
        if key not in allowed:
            breaches.append(f"{key}: {size} lines, over the limit of {limit}")
        elif size > allowed[key]:
            breaches.append(f"{key}: {size} lines, grew past its recorded {allowed[key]}")
    stale = [k for k in allowed if k not in over]
    for key in stale:
        print(f"note: {key} is now within the limits: drop its line from size_exceptions.txt")
    print(f"{len(over)} over the limits, all recorded" if not breaches else "")
    return breaches


def main(argv):
    if len(argv) < 2 or argv[1] not in ("rules", "sizes"):
        print(__doc__.strip(), file=sys.stderr)
        return 2
    breaches = check_rules() if argv[1] == "rules" else check_sizes("--update" in argv)
    for b in breaches:
        print(b)
    if argv[1] == "rules" and not breaches:
        print("layout rules hold: include/ has no support code; internal/ headers stay in their package")
    return 1 if breaches else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
