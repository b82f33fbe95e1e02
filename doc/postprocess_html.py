#!/usr/bin/env python3
# Copyright (c) 2026 CGAL Global Shape Analysis contributors.
# SPDX-License-Identifier: LGPL-3.0-or-later
"""Numbers the figures of the HTML manual, after doxygen (run by the `doc` target).

A figure is written with \\cgalFigureBegin{id,file} ... \\cgalFigureEnd (doc/Doxyfile.in), which
doxygen turns into an anchor `id` followed by a `cgal-figure` block whose caption starts with
<b class="cgal-figure-number">Figure</b>. This script numbers the figures of every page in their
order (Figure 1, Figure 2, ...), writes the number into the caption, and gives every link to a
figure (\\cgalFigureRef{id}) the text "Figure N", on any page.

    postprocess_html.py <html directory>
"""

import os
import re
import sys

FIGURE = re.compile(r'<a class="anchor" id="([^"]+)"></a>(?:</p>)?\s*<div class="cgal-figure">')
CAPTION = '<b class="cgal-figure-number">Figure</b>'
NUMBERED = re.compile(r'<b class="cgal-figure-number">Figure( \d+:)?</b>')


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    html = sys.argv[1]
    pages = sorted(f for f in os.listdir(html) if f.endswith(".html"))
    texts = {}
    numbers = {}
    for page in pages:
        with open(os.path.join(html, page), encoding="utf-8") as f:
            texts[page] = f.read()
        ids = FIGURE.findall(texts[page])
        for n, figure in enumerate(ids, 1):
            numbers[figure] = n
        # Number the captions in their order (again from 1 when the script runs twice).
        counter = iter(range(1, len(ids) + 1))
        texts[page] = NUMBERED.sub(
            lambda m: '<b class="cgal-figure-number">Figure %d:</b>' % next(counter, 0),
            texts[page])
    if numbers:
        link = re.compile(r'(<a class="el" href="[^"#]*#(%s)">)[^<]*(</a>)'
                          % "|".join(re.escape(i) for i in numbers))
        for page in pages:
            texts[page] = link.sub(
                lambda m: "%sFigure %d%s" % (m.group(1), numbers[m.group(2)], m.group(3)),
                texts[page])
    for page in pages:
        path = os.path.join(html, page)
        with open(path, encoding="utf-8") as f:
            if f.read() == texts[page]:
                continue
        with open(path + ".tmp", "w", encoding="utf-8") as f:
            f.write(texts[page])
        os.replace(path + ".tmp", path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
