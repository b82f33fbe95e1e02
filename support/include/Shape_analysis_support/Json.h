// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef SHAPE_ANALYSIS_SUPPORT_JSON_H
#define SHAPE_ANALYSIS_SUPPORT_JSON_H

// JSON of the command-line tool's reports, the benchmarks' figures and the files they read:
// nlohmann-json (Debian nlohmann-json3-dev). Members keep their insertion order, so a report reads
// in the order it was written.

#include <nlohmann/json.hpp>

#include <string>

namespace CGAL {
namespace Shape_analysis_support {

using Json = nlohmann::ordered_json;

// The text of a report: indented by two spaces; NaN and infinities as null (nlohmann's choice);
// bytes that are not UTF-8 (a file name in another encoding) replaced rather than thrown on.
inline std::string to_text(const Json& j)
{
  return j.dump(2, ' ', false, Json::error_handler_t::replace);
}

} // namespace Shape_analysis_support
} // namespace CGAL

#endif // SHAPE_ANALYSIS_SUPPORT_JSON_H
