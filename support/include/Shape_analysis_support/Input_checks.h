// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef SHAPE_ANALYSIS_SUPPORT_INPUT_CHECKS_H
#define SHAPE_ANALYSIS_SUPPORT_INPUT_CHECKS_H

// Checks of input files made before CGAL's readers see them, for the tool (the library's readers
// make the same checks themselves).

#include <CGAL/Shape_analysis/internal/Ply_header.h>

#include <string>

namespace CGAL {
namespace Shape_analysis_support {

// Bad_input, its message starting with `path`, unless the PLY file `path` has a header with
// a vertex element that has x, y and z properties (CGAL's reader puts vertices without them at
// the origin).
inline void check_ply_vertices(const std::string& path)
{
  CGAL::Shape_analysis::internal::read_ply_header(path);
}

} // namespace Shape_analysis_support
} // namespace CGAL

#endif // SHAPE_ANALYSIS_SUPPORT_INPUT_CHECKS_H
