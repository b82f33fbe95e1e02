// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHAPE_ANALYSIS_BAD_INPUT_H
#define CGAL_SHAPE_ANALYSIS_BAD_INPUT_H

/// \file Bad_input.h
/// The exception that every function of the Global Shape Analysis packages throws on input it
/// cannot process.

#include <stdexcept>
#include <string>

namespace CGAL {
namespace Shape_analysis {

/*!
\ingroup PkgShapeAnalysisCore
Thrown by the functions of the Global Shape Analysis packages when their input cannot be
processed: an empty mesh, a face that is not a triangle, a coordinate that is not finite, a
parameter out of its range, a label map of the wrong size... `what()` says, in one line, what is
wrong. The input is left unchanged and no output map is written.
*/
class Bad_input : public std::invalid_argument
{
public:
  explicit Bad_input(const std::string& what) : std::invalid_argument(what) {}
};

} // namespace Shape_analysis
} // namespace CGAL

#endif // CGAL_SHAPE_ANALYSIS_BAD_INPUT_H
