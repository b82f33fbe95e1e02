// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_POINT_SET_OBJECT_RECOGNITION_LAS_GEOREFERENCE_H
#define CGAL_POINT_SET_OBJECT_RECOGNITION_LAS_GEOREFERENCE_H

/// \file Las_georeference.h

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace CGAL {
namespace Point_set_object_recognition {

/*!
\ingroup PkgPointSetObjectRecognitionRef

Where a LAS file puts its points on the Earth: the scale and offset of its integer coordinates
and its coordinate reference system (CRS) records. `read_point_set()` and
`Point_set_file_reader` return it for a LAS file; given to `write_las_point_set()` or
`Las_point_set_pieces` (named parameter `las_georeference`), the file written has the same
scale, offset and CRS records, so that points read and written again keep their integer
coordinates exactly and GIS tools place them where the scan was.
*/
struct Las_georeference
{
  /// A coordinate system record: a variable length record (or an extended one, LAS 1.4) of user
  /// id `LASF_Projection` (GeoTIFF keys 34735, 34736, 34737; OGC WKT 2111, 2112).
  struct Record
  {
    std::uint16_t record_id = 0;           ///< the record id
    std::string description;               ///< its description (at most 32 characters kept)
    std::vector<unsigned char> data;       ///< its payload, as in the file
  };

  /// the scale of the stored integer coordinates, per axis: a coordinate is `integer * scale +
  /// offset`
  std::array<double, 3> scale{{0.001, 0.001, 0.001}};
  /// the offset of the stored integer coordinates, per axis
  std::array<double, 3> offset{{0, 0, 0}};
  /// the CRS records, in the order of the file (its VLRs, then its extended VLRs)
  std::vector<Record> crs_records;
  /// whether the file declares its CRS as OGC WKT (bit 4 of the global encoding); written so when
  /// the records are WKT or there are none, so that GeoTIFF keys of a LAS 1.2 file are still
  /// found by readers in the LAS 1.4 file written
  bool wkt = false;
};

} // namespace Point_set_object_recognition
} // namespace CGAL

#endif // CGAL_POINT_SET_OBJECT_RECOGNITION_LAS_GEOREFERENCE_H
