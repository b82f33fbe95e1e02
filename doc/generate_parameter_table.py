#!/usr/bin/env python3
# Copyright (c) 2026 CGAL Global Shape Analysis contributors.
# SPDX-License-Identifier: LGPL-3.0-or-later
"""Writes the page of the manual that lists every named parameter.

Run by the `doc` target before doxygen (see doc/CMakeLists.txt), so the list cannot drift from the
code:

- the parameters of this library are the entries of the X-macro list
  CGAL_SHAPE_ANALYSIS_NAMED_PARAMETER_LIST in include/CGAL/Shape_analysis/parameters.h, in its
  order;
- the parameters of CGAL that the packages read are those of CGAL's own list
  (CGAL/STL_Extension/internal/parameters_interface.h) that a public header documents in a
  \\cgalParamNBegin block or that a header of include/CGAL/<Package>/ reads through its tag
  (`CGAL::internal_np::<tag>`);
- for every parameter, the public functions whose doxygen comment has a \\cgalParamNBegin block
  naming it, with a link, its description and its default there.

    generate_parameter_table.py --source-dir <project> --cgal-include-dir <dir> --output <file.txt>
"""

import argparse
import os
import re
import sys

PACKAGES = ["Consistent_segmentation", "Randomized_cuts", "Surface_mesh_symmetrization",
            "Point_set_object_recognition", "Shape_analysis"]


def read(path):
    with open(path, encoding="utf-8") as f:
        return f.read()


def library_parameters(parameters_h):
    """The names of the X-macro list, in order."""
    text = read(parameters_h)
    start = text.find("#define CGAL_SHAPE_ANALYSIS_NAMED_PARAMETER_LIST(X)")
    if start < 0:
        sys.exit("generate_parameter_table.py: no CGAL_SHAPE_ANALYSIS_NAMED_PARAMETER_LIST in "
                 + parameters_h)
    body = []
    for line in text[start:].splitlines()[1:]:
        body.append(line)
        if not line.rstrip().endswith("\\"):
            break
    names = re.findall(r"X\(\s*\w+\s*,\s*\w+\s*,\s*(\w+)\s*\)", "\n".join(body))
    if not names:
        sys.exit("generate_parameter_table.py: the named-parameter list of " + parameters_h
                 + " is empty")
    return names


def cgal_parameters(cgal_include_dir):
    """CGAL's parameters: tag value -> name, and the names in their order."""
    path = os.path.join(cgal_include_dir, "CGAL", "STL_Extension", "internal",
                        "parameters_interface.h")
    tag_to_name = {}
    names = []
    for tag_type, tag, name in re.findall(
            r"^\s*CGAL_add_named_parameter\(\s*(\w+)\s*,\s*(\w+)\s*,\s*(\w+)\s*\)", read(path),
            re.M):
        tag_to_name[tag] = name
        names.append(name)
    return tag_to_name, names


def matching_brace(text, open_index):
    """The index of the brace that closes the one at open_index (or len(text))."""
    depth = 0
    for i in range(open_index, len(text)):
        if text[i] == "{":
            depth += 1
        elif text[i] == "}":
            depth -= 1
            if depth == 0:
                return i
    return len(text)


def command_argument(block, command):
    """The argument of the first `\\command{...}` of block, braces matched, on one line."""
    i = block.find("\\" + command + "{")
    if i < 0:
        return ""
    open_index = i + len(command) + 1
    close = matching_brace(block, open_index)
    return " ".join(block[open_index + 1:close].split())


def documented_entity(code):
    """The name of the function (or class) that the code after a doxygen comment declares."""
    code = re.sub(r"//[^\n]*", "", code)
    # Drop template parameter lists, whose defaults may hold parentheses.
    while True:
        m = re.search(r"\btemplate\s*<", code)
        if not m:
            break
        depth, i = 0, m.end() - 1
        while i < len(code):
            if code[i] == "<":
                depth += 1
            elif code[i] == ">":
                depth -= 1
                if depth == 0:
                    break
            i += 1
        code = code[:m.start()] + code[i + 1:]
    m = re.match(r"\s*(?:struct|class)\s+(\w+)", code)
    if m:
        return m.group(1), False
    for m in re.finditer(r"(~?\w+)\s*\(", code):
        if m.group(1) not in ("decltype", "alignof", "sizeof", "noexcept"):
            return m.group(1), True
    return None, False


def doc_blocks(text):
    """(comment, code that follows) for every /*! ... */ comment of a header."""
    for m in re.finditer(r"/\*!(.*?)\*/", text, re.S):
        yield m.group(1), text[m.end():m.end() + 2000]


def parameter_blocks(comment):
    """(names, block text) for every \\cgalParamNBegin{...} ... \\cgalParamNEnd of a comment."""
    for m in re.finditer(r"\\cgalParamNBegin\{", comment):
        close = matching_brace(comment, m.end() - 1)
        names = [n.strip() for n in re.split(r"[/,]", comment[m.end():close]) if n.strip()]
        end = comment.find("\\cgalParamNEnd", close)
        yield names, comment[close + 1:end if end >= 0 else len(comment)]


def function_readers(source_dir):
    """parameter -> [(package, function, description, default)], in the order of the packages."""
    readers = {}
    structs = options_structs(source_dir)
    for package in PACKAGES:
        directory = os.path.join(source_dir, "include", "CGAL", package)
        if not os.path.isdir(directory):
            continue
        for name in sorted(os.listdir(directory)):
            if not name.endswith(".h"):
                continue
            text = read(os.path.join(directory, name))
            for comment, code in doc_blocks(text):
                if "\\cgalParamNBegin" not in comment:
                    continue
                entity, is_function = documented_entity(code)
                if entity is None:
                    continue
                for names, block in parameter_blocks(comment):
                    description = command_argument(block, "cgalParamDescription")
                    default = resolve_default(command_argument(block, "cgalParamDefault"), structs)
                    for parameter in names:
                        entry = (package, entity, is_function, description, default)
                        known = readers.setdefault(parameter, [])
                        if all(e[:3] != entry[:3] for e in known):
                            known.append(entry)
    return readers


def options_structs(source_dir):
    """struct name -> (base struct name or None, {member: initializer}) for the public options
    structs (`*_options`) of the packages: where the defaults are written."""
    structs = {}
    for package in PACKAGES:
        directory = os.path.join(source_dir, "include", "CGAL", package)
        if not os.path.isdir(directory):
            continue
        for name in sorted(os.listdir(directory)):
            if not name.endswith(".h"):
                continue
            text = read(os.path.join(directory, name))
            for m in re.finditer(r"\bstruct\s+(\w+_options)\s*(?::\s*(?:public\s+)?([\w:]+))?\s*\{", text):
                close = matching_brace(text, m.end() - 1)
                body = re.sub(r"//[^\n]*", "", text[m.end():close])
                members = {}
                for d in re.finditer(r"(\w+)\s*=\s*([^;]+);", body):
                    members[d.group(1)] = " ".join(d.group(2).split())
                base = m.group(2).split("::")[-1] if m.group(2) else None
                structs[m.group(1)] = (base, members)
    # The Core's shared defaults (CGAL/Shape_analysis/defaults.h), which initializers may name.
    core = os.path.join(source_dir, "include", "CGAL", "Shape_analysis", "defaults.h")
    if os.path.exists(core):
        for d in re.finditer(r"constexpr\s+[\w:]+\s+(\w+)\s*=\s*([^;]+);", read(core)):
            structs.setdefault("", (None, {}))[1]["CGAL::Shape_analysis::" + d.group(1)] = d.group(2).strip()
    return structs


def resolve_default(default, structs):
    """A default given as `Some_options::member` shown with its value, read from the struct."""
    m = re.fullmatch(r"\s*`?(\w+_options)::(\w+)`?\s*", default or "")
    if not m:
        return default
    struct, member = m.group(1), m.group(2)
    while struct in structs:
        base, members = structs[struct]
        if member in members:
            value = members[member]
            value = structs.get("", (None, {}))[1].get(value, value)  # a Core constant's value
            return "`%s` (`%s::%s`)" % (value, m.group(1), member)
        struct = base
    return default


def tags_read(source_dir, tag_to_name):
    """CGAL parameters whose tags the headers of the packages use."""
    used = set()
    for package in PACKAGES:
        for root, _, files in os.walk(os.path.join(source_dir, "include", "CGAL", package)):
            for name in files:
                if name.endswith(".h"):
                    for tag in re.findall(r"CGAL::internal_np::(\w+)", read(os.path.join(root, name))):
                        if tag in tag_to_name:
                            used.add(tag_to_name[tag])
    return used


def link(package, entity, is_function):
    qualified = "CGAL::" + package + "::" + entity
    if is_function:
        return '\\ref %s() "%s()"' % (qualified, entity)
    return '\\ref %s "%s"' % (qualified, entity)


def rows(parameters, readers):
    out = []
    for parameter in parameters:
        entries = readers.get(parameter, [])
        if entries:
            descriptions = []
            for package, entity, is_function, description, default in entries:
                item = "<li>" + link(package, entity, is_function)
                if description:
                    item += ": " + description
                if default:
                    item += " <em>(default: " + default + ")</em>"
                descriptions.append(item + "</li>")
            cell = "<ul>" + "".join(descriptions) + "</ul>"
        else:
            cell = "read by the packages' internal code, documented by no public function"
        out.append('<tr><td class="paramname"><code>%s</code></td><td>%s</td></tr>'
                   % (parameter, cell))
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--source-dir", required=True)
    parser.add_argument("--cgal-include-dir", required=True)
    parser.add_argument("--output", required=True)
    args = parser.parse_args()

    ours = library_parameters(os.path.join(args.source_dir, "include", "CGAL", "Shape_analysis",
                                           "parameters.h"))
    tag_to_name, cgal_names = cgal_parameters(args.cgal_include_dir)
    readers = function_readers(args.source_dir)
    ours_set = set(ours)
    used = tags_read(args.source_dir, tag_to_name) | {
        p for p in readers if p in cgal_names and p not in ours_set}
    theirs = [n for n in sorted(set(cgal_names)) if n in used and n not in ours_set]
    unknown = sorted(p for p in readers if p not in ours_set and p not in set(cgal_names))
    if unknown:
        sys.exit("generate_parameter_table.py: documented parameters that neither this library nor "
                 "CGAL defines: " + ", ".join(unknown))

    lines = [
        "/*!",
        "\\page ShapeAnalysisParameterList Complete List of Named Parameters",
        "",
        "This page is generated when the manual is built (by `doc/generate_parameter_table.py`): "
        "from the list of named parameters of `CGAL/Shape_analysis/parameters.h` "
        "(%d parameters), from the parameters of \\cgal that the packages read (%d), and from "
        "the reference documentation of every public function, whose description and default "
        "are quoted here. A parameter read by several functions may have a different default in "
        "each; the function's reference page is the authority. How to pass them is explained in "
        "\\ref ShapeAnalysisNamedParameters." % (len(ours), len(theirs)),
        "",
        "\\section ShapeAnalysisParameterListOurs Parameters Defined by this Library",
        "",
        '<table class="cgal-parameter-list">',
        "<tr><th>Parameter</th><th>Documented by (the description and the default there)</th></tr>",
    ]
    lines += rows(ours, readers)
    lines += [
        "</table>",
        "",
        "\\section ShapeAnalysisParameterListCgal Parameters of CGAL Read by the Packages",
        "",
        '<table class="cgal-parameter-list">',
        "<tr><th>Parameter</th><th>Documented by (the description and the default there)</th></tr>",
    ]
    lines += rows(theirs, readers)
    lines += ["</table>", "*/", ""]
    text = "\n".join(lines)

    # Rewrite only when the text changes, so that doxygen does not run again for nothing.
    if os.path.exists(args.output) and read(args.output) == text:
        return 0
    os.makedirs(os.path.dirname(os.path.abspath(args.output)), exist_ok=True)
    with open(args.output + ".tmp", "w", encoding="utf-8") as f:
        f.write(text)
    os.replace(args.output + ".tmp", args.output)
    return 0


if __name__ == "__main__":
    sys.exit(main())
