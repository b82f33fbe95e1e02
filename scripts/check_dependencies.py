#!/usr/bin/env python3
# Copyright (c) 2026 CGAL Global Shape Analysis contributors.
# SPDX-License-Identifier: LGPL-3.0-or-later
"""Regenerates package_info/<Package>/dependencies from the #include lines of the headers.

For every package of this library (a directory include/CGAL/<Package>/), the script reads the
`#include <CGAL/...>` lines of the package's own headers (include/CGAL/<Package>/, internal/
included; the headers they include are not followed) and names the package of each included
header:

- a header of another package of this library (include/CGAL/<Other>/...) is that package,
  for example Shape_analysis;
- a header of CGAL is looked up in CGAL's installed headers, whose `$URL:` line names the package
  it comes from (`.../CGAL/cgal/blob/v5.5.1/<Package>/include/CGAL/...`).

The sorted list of these packages is what package_info/<Package>/dependencies holds.

    scripts/check_dependencies.py            rewrite the files that are stale
    scripts/check_dependencies.py --check    exit 1 and print the differences when a file is stale
                                             (run by ctest as package_dependencies_up_to_date)

--cgal-include-dir DIR gives CGAL's include directory (default: the first of /usr/include and
/usr/local/include that holds CGAL/version.h).
"""

import argparse
import difflib
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
INCLUDE = re.compile(r'^\s*#\s*include\s*<(CGAL/[^>]+)>', re.M)
URL = re.compile(r'\$URL:[^$]*/blob/[^/]+/([^/]+)/include/CGAL/')


def packages_of_library(root):
    """The packages of this library: the directories of include/CGAL holding headers."""
    base = os.path.join(root, "include", "CGAL")
    result = []
    for name in sorted(os.listdir(base)):
        directory = os.path.join(base, name)
        if os.path.isdir(directory) and any(
                f.endswith(".h") for _, _, files in os.walk(directory) for f in files):
            result.append(name)
    return result


def cgal_package(header, cgal_include_dir, cache):
    """The CGAL package that an installed header (path relative to the include dir) belongs to."""
    if header in cache:
        return cache[header]
    path = os.path.join(cgal_include_dir, header)
    if not os.path.isfile(path):
        raise LookupError("%s is not installed in %s" % (header, cgal_include_dir))
    with open(path, encoding="utf-8", errors="replace") as f:
        head = f.read(4000)
    m = URL.search(head)
    if not m:
        raise LookupError("%s has no $URL line naming its package" % path)
    cache[header] = m.group(1)
    return cache[header]


def dependencies(root, package, ours, cgal_include_dir, cache):
    """The sorted packages that the headers of one package include directly."""
    found = set()
    problems = []
    directory = os.path.join(root, "include", "CGAL", package)
    for base, _, files in sorted(os.walk(directory)):
        for name in sorted(files):
            if not name.endswith(".h"):
                continue
            path = os.path.join(base, name)
            with open(path, encoding="utf-8") as f:
                text = f.read()
            for header in INCLUDE.findall(text):
                first = header.split("/")[1] if header.count("/") >= 2 else None
                if first in ours:
                    if first != package:
                        found.add(first)
                    continue
                try:
                    found.add(cgal_package(header, cgal_include_dir, cache))
                except LookupError as e:
                    problems.append("%s: %s" % (os.path.relpath(path, root), e))
    return sorted(found), problems


def default_cgal_include_dir():
    for d in ("/usr/include", "/usr/local/include"):
        if os.path.isfile(os.path.join(d, "CGAL", "version.h")):
            return d
    return "/usr/include"


def main():
    parser = argparse.ArgumentParser(
        description="Regenerates package_info/<Package>/dependencies from the includes.")
    parser.add_argument("--check", action="store_true",
                        help="change nothing; exit 1 and print the differences if a file is stale")
    parser.add_argument("--cgal-include-dir", default=default_cgal_include_dir())
    parser.add_argument("--root", default=ROOT, help="the project's source directory")
    args = parser.parse_args()

    ours = packages_of_library(args.root)
    cache = {}
    stale = []
    problems = []
    for package in ours:
        deps, issues = dependencies(args.root, package, ours, args.cgal_include_dir, cache)
        problems += issues
        path = os.path.join(args.root, "package_info", package, "dependencies")
        wanted = "".join(d + "\n" for d in deps)
        current = None
        if os.path.isfile(path):
            with open(path, encoding="utf-8") as f:
                current = f.read()
        if current == wanted:
            continue
        stale.append(os.path.relpath(path, args.root))
        if args.check:
            sys.stdout.writelines(difflib.unified_diff(
                (current or "").splitlines(True), wanted.splitlines(True),
                fromfile=os.path.relpath(path, args.root) + " (in the repository)",
                tofile=os.path.relpath(path, args.root) + " (from the includes)"))
        else:
            os.makedirs(os.path.dirname(path), exist_ok=True)
            with open(path + ".tmp", "w", encoding="utf-8") as f:
                f.write(wanted)
            os.replace(path + ".tmp", path)
            print("updated " + os.path.relpath(path, args.root))
    for p in problems:
        print("error: " + p, file=sys.stderr)
    if problems:
        return 2
    if args.check and stale:
        print("stale: %s; run scripts/check_dependencies.py to update" % ", ".join(stale))
        return 1
    if args.check:
        print("package_info/*/dependencies are up to date (%d packages)" % len(ours))
    return 0


if __name__ == "__main__":
    sys.exit(main())
