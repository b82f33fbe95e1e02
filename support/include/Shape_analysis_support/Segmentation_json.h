// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef SHAPE_ANALYSIS_SUPPORT_SEGMENTATION_JSON_H
#define SHAPE_ANALYSIS_SUPPORT_SEGMENTATION_JSON_H

// The evaluation of segmentations (segment_objects.h) as JSON, for the command-line tool and the
// benchmark: counts, overall and per-class precision and recall.

#include <CGAL/Point_set_object_recognition/segment_objects.h>
#include <Shape_analysis_support/Json.h>

#include <functional>
#include <string>

namespace CGAL {
namespace Shape_analysis_support {

inline Json segmentation_evaluation_json(const CGAL::Point_set_object_recognition::Segmentation_evaluation& e,
                                         const std::function<std::string(int)>& class_name)
{
  Json j = Json::object();
  j["matched"] = e.objects.size();
  j["unmatched"] = e.unmatched;
  j["precision"] = e.precision;
  j["recall"] = e.recall;
  Json classes = Json::array();
  for(const CGAL::Point_set_object_recognition::Class_segmentation_score& c : e.classes) {
    Json jc = Json::object();
    jc["class"] = class_name(c.object_class);
    jc["objects"] = c.objects;
    jc["precision"] = c.precision;
    jc["recall"] = c.recall;
    classes.push_back(jc);
  }
  j["classes"] = classes;
  return j;
}

} // namespace Shape_analysis_support
} // namespace CGAL

#endif // SHAPE_ANALYSIS_SUPPORT_SEGMENTATION_JSON_H
