// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_SEGMENTATION_JSON_H
#define CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_SEGMENTATION_JSON_H

// The evaluation of segmentations (segment_objects.h) as JSON, for the command-line tool and the
// benchmark: counts, overall and per-class precision and recall.

#include <CGAL/Point_set_object_recognition/segment_objects.h>
#include <CGAL/Shape_analysis/internal/Json.h>

#include <functional>
#include <string>

namespace CGAL {
namespace Point_set_object_recognition {
namespace internal {

inline CGAL::Shape_analysis::internal::Json
segmentation_evaluation_json(const Segmentation_evaluation& e, const std::function<std::string(int)>& class_name)
{
  typedef CGAL::Shape_analysis::internal::Json Json;
  Json j = Json::object();
  j["matched"] = e.objects.size();
  j["unmatched"] = e.unmatched;
  j["precision"] = e.precision;
  j["recall"] = e.recall;
  Json classes = Json::array();
  for(const Class_segmentation_score& c : e.classes) {
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

} // namespace internal
} // namespace Point_set_object_recognition
} // namespace CGAL

#endif // CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_SEGMENTATION_JSON_H
