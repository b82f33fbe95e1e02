// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_POINT_SET_OBJECT_RECOGNITION_OBJECT_CONTEXT_H
#define CGAL_POINT_SET_OBJECT_RECOGNITION_OBJECT_CONTEXT_H

/// \file Object_context.h
/// Context features of candidate objects (thesis section 4.3.4): the distance to the nearest
/// street, and the class "autocorrelation" grids that score how well a candidate fits the
/// patterns of the objects of each class around it (lamp posts every 30 m along the street...).

#include <CGAL/Point_set_object_recognition/Street_map.h>
#include <CGAL/Point_set_object_recognition/internal/Horizontal_buckets.h>
#include <CGAL/Point_set_object_recognition/internal/Token_reader.h>
#include <CGAL/Shape_analysis/Bad_input.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iomanip>
#include <istream>
#include <limits>
#include <ostream>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Point_set_object_recognition {

/*!
\ingroup PkgPointSetObjectRecognitionRef
The options of `Context_grids::learn()`, with their defaults (saved with the grids).
*/
struct Context_grid_options
{
  /// the side of a cell of the grids (metres, positive)
  double cell_size = 1.0;
  /// the half side of the grids (metres, at least `cell_size`, at most 2000 cells per side): a
  /// grid covers the objects within `extent` of an object along and across its street (40 m: a
  /// row of lamp posts 30 m apart shows)
  double extent = 40.0;
  /// the standard deviation of the Gaussian over which each object is spread in the grids
  /// (metres, at least 0), cut at 3 deviations; 0: the object counts in its cell only (as when
  /// no cell centre lies within 3 deviations). It absorbs the jitter of a pattern and of the
  /// locations.
  double smoothing = 1.0;
  /// objects closer than this to each other (metres, at least 0) are taken for the same object:
  /// such pairs are not counted when learning, and a labelled object this close to a candidate
  /// does not contribute to the candidate's prediction (it is the candidate itself, or its true
  /// object when training)
  double self_radius = 1.0;
};

/// \cond SKIP_IN_MANUAL
namespace internal {

// An object's frame: origin at the object, `along` and `across` unit axes.
struct Object_frame
{
  double x = 0, y = 0;
  std::array<double, 2> along{{1, 0}}, across{{0, 1}};

  std::array<double, 2> coordinates(double px, double py) const
  {
    const double dx = px - x, dy = py - y;
    return {{dx * along[0] + dy * along[1], dx * across[0] + dy * across[1]}};
  }
};

// The frame of the object at (x, y): across its nearest street pointing away from it (the left
// normal when the object lies on the street's line), along the street with (along, across)
// counter-clockwise; the scan's axes when the map is empty.
inline Object_frame object_frame(const Street_map& map, double x, double y)
{
  Object_frame f;
  f.x = x, f.y = y;
  if(map.empty())
    return f;
  const Street_point s = map.nearest(x, y);
  const std::array<double, 2> d = s.direction, left{{-d[1], d[0]}};
  const double side = (x - s.point[0]) * left[0] + (y - s.point[1]) * left[1];
  f.across = side < 0 ? std::array<double, 2>{{-left[0], -left[1]}} : left;
  f.along = {{f.across[1], -f.across[0]}};
  return f;
}

inline void check_context_grid_options(const Context_grid_options& o)
{
  const std::string who = "Context_grids: ";
  if(!(o.cell_size > 0) || !std::isfinite(o.cell_size))
    throw Bad_input(who + "the cell size must be positive and finite");
  if(!(o.extent >= o.cell_size) || !std::isfinite(o.extent) || o.extent / o.cell_size > 1000)
    throw Bad_input(who + "the extent must be at least the cell size and at most 1000 cells");
  if(!(o.smoothing >= 0) || !std::isfinite(o.smoothing) || o.smoothing / o.cell_size > 100)
    throw Bad_input(who + "the smoothing must be finite, at least 0 and at most 100 cells");
  if(!(o.self_radius >= 0) || !std::isfinite(o.self_radius))
    throw Bad_input(who + "the self radius must be finite and at least 0");
}

} // namespace internal
/// \endcond

/*!
\ingroup PkgPointSetObjectRecognitionRef

The class "autocorrelation" grids of the thesis (section 4.3.4) and the "prediction" they make at
candidate objects: objects of a class stand in patterns (lamp posts every 30 m along the street,
parking meters in rows, newspaper boxes in groups), and a candidate that fits the pattern of the
objects of a class already found around it is more likely of that class.

<b>Frames.</b> Each object has a frame: origin at the object, one axis across its nearest street
pointing away from the street (toward the buildings on its side), the other along the street (the
pair counter-clockwise). Objects on the other side of the street thus lie at negative across
coordinates, about twice the object's distance away. Without a street map (an empty
`Street_map`), the frame is the scan's axes: along \f$ x \f$, across \f$ y \f$; grids learned
that way suit scans whose street runs along \f$ x \f$ only, and are marked so (`uses_streets()`):
grids learned with a map need a map to predict, and grids learned without one need none.

<b>Learning</b> (`learn()`): per class \f$ c \f$, a 2D histogram of the positions, in the frame of
each object of class \f$ c \f$, of the other objects of class \f$ c \f$ within the grid, each
spread over a Gaussian of deviation `Context_grid_options::smoothing`. As the sense of the along
axis only follows the side of the street, each object counts half at \f$ (a, b) \f$ and half at
\f$ (-a, b) \f$: the grids are symmetric along the street. The histogram is divided by the number
of objects of class \f$ c \f$ and by the area of a cell: a value is the expected number of other
objects of class \f$ c \f$ per square metre at that position of an object of class \f$ c \f$.

<b>Prediction</b> (`prediction()`): for a candidate and a class \f$ c \f$, the sum over the
labelled objects \f$ j \f$ of class \f$ c \f$ (at least `self_radius` away from the candidate) of
the value of the grid of \f$ c \f$ at the candidate's position in \f$ j \f$'s frame (bilinear
between cell centres, 0 outside the grid): the density of class-\f$ c \f$ objects that the
labelled objects predict at the candidate. When training a classifier, the labelled objects are
the true objects of the training scan; when classifying, they are the output of a first
classification without context (see `context_features()`).

Copies are independent; the `const` functions are safe to call from several threads at once.
*/
class Context_grids
{
public:
  /// Grids not learned yet: `prediction()` and `save()` throw until `learn()` or `load()`.
  Context_grids() = default;

  /// \returns whether `learn()` or `load()` succeeded
  bool is_trained() const { return m_classes != 0; }
  /// \returns the number of classes (0 when not trained)
  std::size_t number_of_classes() const { return m_classes; }
  /// \returns the options the grids were learned with
  const Context_grid_options& options() const { return m_options; }
  /// \returns whether the grids were learned in the frames of the streets (else of the scan's axes)
  bool uses_streets() const { return m_streets; }
  /// \returns the number of cells per side of a grid
  std::size_t cells_per_side() const { return m_n; }
  /// \param c a class index, below `number_of_classes()`
  /// \returns the number of objects of class `c` that the grids were learned from
  std::size_t number_of_objects(std::size_t c) const { return m_objects.at(c); }

  /// The value of the grid of class `c` at a position of an object's frame.
  /// \param c a class index, below `number_of_classes()`
  /// \param along the coordinate along the street (metres)
  /// \param across the coordinate across the street, positive away from it (metres)
  /// \returns the value, bilinear between cell centres, 0 outside the grid
  /// \throws CGAL::Shape_analysis::Bad_input when `c` is not below `number_of_classes()`
  double value(std::size_t c, double along, double across) const
  {
    if(c >= m_classes)
      throw Bad_input("Context_grids::value: class " + std::to_string(c) + " is not below the number of classes " +
                      std::to_string(m_classes));
    return interpolate(m_grids[c], along, across);
  }

  /*!
  Learns the grids from the objects of a labelled scan, replacing any previous grids.
  \tparam LabelledRange a range of objects with members `position` (an indexable
          \f$ (x, y, \ldots) \f$, e.g. `std::array<double, 3>`) and `label` (a class index), for
          example `std::vector<Labelled_location>`
  \param objects the objects and their classes, in the coordinates of the scan
  \param number_of_classes the number of classes (at least 1); every label is below it
  \param map the streets of the scan, or an empty map (the frames are then the scan's axes)
  \param options the options (see `Context_grid_options`)
  \throws CGAL::Shape_analysis::Bad_input (the grids unchanged) when `objects` is empty, a label
          is not below `number_of_classes`, a position is not finite, `number_of_classes` is 0 or
          over \f$ 2^{16} \f$, or an option is out of its range
  */
  template <typename LabelledRange>
  void learn(const LabelledRange& objects, std::size_t number_of_classes, const Street_map& map,
             const Context_grid_options& options = Context_grid_options())
  {
    internal::check_context_grid_options(options);
    if(number_of_classes == 0 || number_of_classes > (std::size_t(1) << 16))
      throw Bad_input("Context_grids::learn: the number of classes must be between 1 and 65536");
    std::vector<std::array<double, 2>> xy;
    std::vector<std::size_t> labels;
    gather(objects, xy, labels, number_of_classes, true, "Context_grids::learn");
    if(xy.empty())
      throw Bad_input("Context_grids::learn: no labelled object");
    Context_grids g;
    g.m_options = options, g.m_classes = number_of_classes, g.m_streets = !map.empty();
    g.m_n = cells(options);
    g.m_grids.assign(number_of_classes, std::vector<double>(g.m_n * g.m_n, 0.0));
    g.m_objects.assign(number_of_classes, 0);
    for(std::size_t l : labels)
      ++g.m_objects[l];
    // Objects up to a kernel's radius outside the grid still spread into it.
    const double half = 0.5 * double(g.m_n) * options.cell_size + 3 * options.smoothing + options.cell_size;
    const double reach = half * std::sqrt(2.0);
    const internal::Horizontal_buckets buckets(xy, reach);
    for(std::size_t i = 0; i < xy.size(); ++i) {
      const internal::Object_frame f = internal::object_frame(map, xy[i][0], xy[i][1]);
      buckets.around(xy[i][0], xy[i][1], reach, [&](std::size_t j) {
        if(j == i || labels[j] != labels[i] ||
           std::hypot(xy[j][0] - xy[i][0], xy[j][1] - xy[i][1]) < options.self_radius)
          return;
        const std::array<double, 2> ab = f.coordinates(xy[j][0], xy[j][1]);
        if(std::abs(ab[0]) < half && std::abs(ab[1]) < half) {
          g.splat(g.m_grids[labels[i]], ab[0], ab[1], 0.5);
          g.splat(g.m_grids[labels[i]], -ab[0], ab[1], 0.5);
        }
      });
    }
    const double area = options.cell_size * options.cell_size;
    for(std::size_t c = 0; c < number_of_classes; ++c)
      if(g.m_objects[c] != 0)
        for(double& v : g.m_grids[c])
          v /= double(g.m_objects[c]) * area;
    *this = std::move(g);
  }

  /*!
  The prediction of each class at candidate locations from labelled objects around them (see the
  class description).
  \tparam LabelledRange as for `learn()`, for example `std::vector<Labelled_location>`
  \param locations the candidates, \f$ (x, y, z) \f$ in the coordinates of the scan
  \param labelled the labelled objects; those whose label is not below `number_of_classes()`
         (the class `background` of a classifier) are ignored
  \param map the streets of the scan: a map if the grids were learned with one, else an empty map
  \returns per location, per class, the predicted density (objects per square metre)
  \throws CGAL::Shape_analysis::Bad_input when the grids are not trained, when `map` is empty but
          the grids were learned with streets or the reverse, or when a position is not finite
  */
  template <typename LabelledRange>
  std::vector<std::vector<double>> prediction(const std::vector<std::array<double, 3>>& locations,
                                              const LabelledRange& labelled, const Street_map& map) const
  {
    const std::string who = "Context_grids::prediction";
    if(!is_trained())
      throw Bad_input(who + ": the grids are not learned (learn() or load() first)");
    if(m_streets == map.empty())
      throw Bad_input(who + (m_streets ? ": the grids were learned in the frames of streets, give the street map"
                                       : ": the grids were learned without a street map, give an empty map"));
    std::vector<std::array<double, 2>> xy;
    std::vector<std::size_t> labels;
    gather(labelled, xy, labels, m_classes, false, who);
    std::vector<internal::Object_frame> frames;
    frames.reserve(xy.size());
    for(const std::array<double, 2>& p : xy)
      frames.push_back(internal::object_frame(map, p[0], p[1]));
    // The grid's values fade to 0 half a cell beyond its side.
    const double reach = (0.5 * double(m_n) + 1) * m_options.cell_size * std::sqrt(2.0);
    const internal::Horizontal_buckets buckets(xy, reach);
    std::vector<std::vector<double>> out(locations.size(), std::vector<double>(m_classes, 0.0));
    for(std::size_t i = 0; i < locations.size(); ++i) {
      const double x = locations[i][0], y = locations[i][1];
      if(!std::isfinite(x) || !std::isfinite(y))
        throw Bad_input(who + ": location " + std::to_string(i) + " is not finite");
      buckets.around(x, y, reach, [&](std::size_t j) {
        if(std::hypot(xy[j][0] - x, xy[j][1] - y) < m_options.self_radius)
          return;
        const std::array<double, 2> ab = frames[j].coordinates(x, y);
        out[i][labels[j]] += interpolate(m_grids[labels[j]], ab[0], ab[1]);
      });
    }
    return out;
  }

  /*!
  Writes the grids in a versioned text format (doubles with 17 significant digits, so that
  loaded grids predict bit-identical values):
  \code
  CGAL_Point_set_object_recognition_context_grids 1
  classes <c>
  frames streets | axes
  cell_size <s> extent <e> smoothing <g> self_radius <r>
  cells <n>                      (per side)
  objects <c counts>             (the objects of each class learned from)
  grid <k>  then n rows of n values (row i: across coordinate (i + 0.5 - n / 2) s, columns
            along), for k = 0 ... c - 1
  end
  \endcode
  \param os the stream to write to
  \throws CGAL::Shape_analysis::Bad_input when the grids are not trained
  */
  void save(std::ostream& os) const
  {
    if(!is_trained())
      throw Bad_input("Context_grids::save: the grids are not learned (learn() or load() first)");
    os << "CGAL_Point_set_object_recognition_context_grids 1\nclasses " << m_classes << "\nframes "
       << (m_streets ? "streets" : "axes") << '\n'
       << std::setprecision(17) << "cell_size " << m_options.cell_size << " extent " << m_options.extent
       << " smoothing " << m_options.smoothing << " self_radius " << m_options.self_radius << "\ncells " << m_n
       << "\nobjects";
    for(std::size_t k : m_objects)
      os << ' ' << k;
    os << '\n';
    for(std::size_t c = 0; c < m_classes; ++c) {
      os << "grid " << c << '\n';
      for(std::size_t i = 0; i < m_n; ++i)
        for(std::size_t j = 0; j < m_n; ++j)
          os << m_grids[c][i * m_n + j] << (j + 1 == m_n ? '\n' : ' ');
    }
    os << "end\n";
  }

  /*!
  Reads grids written by `save()`, replacing these.
  \param is the stream to read from
  \throws CGAL::Shape_analysis::Bad_input (the grids unchanged) on a wrong first line, another
          format version, a truncated stream, a value that is not a finite number (or a negative
          grid value), options out of their range or a number of cells that does not match them
  */
  void load(std::istream& is)
  {
    internal::Token_reader r(is, "context grid file");
    r.first_line("CGAL_Point_set_object_recognition_context_grids", "context grids");
    Context_grids g;
    r.expect("classes");
    g.m_classes = r.count("the number of classes", std::size_t(1) << 16);
    if(g.m_classes == 0)
      r.fail("the number of classes is 0");
    r.expect("frames");
    const std::string frames = r.token("the frames");
    if(frames != "streets" && frames != "axes")
      r.fail("frames '" + frames + "', expected 'streets' or 'axes'");
    g.m_streets = frames == "streets";
    const char* names[] = {"cell_size", "extent", "smoothing", "self_radius"};
    double* values[] = {&g.m_options.cell_size, &g.m_options.extent, &g.m_options.smoothing, &g.m_options.self_radius};
    for(int k = 0; k < 4; ++k) {
      r.expect(names[k]);
      *values[k] = r.real(std::string("the ") + names[k]);
    }
    try {
      internal::check_context_grid_options(g.m_options);
    } catch(const Bad_input& e) {
      r.fail(e.what());
    }
    r.expect("cells");
    g.m_n = r.count("the number of cells", 2000);
    if(g.m_n != cells(g.m_options))
      r.fail("the number of cells " + std::to_string(g.m_n) + " does not match the cell size and extent");
    r.expect("objects");
    for(std::size_t c = 0; c < g.m_classes; ++c)
      g.m_objects.push_back(r.count("the number of objects of a class", std::size_t(1) << 40));
    g.m_grids.assign(g.m_classes, std::vector<double>(g.m_n * g.m_n, 0.0));
    for(std::size_t c = 0; c < g.m_classes; ++c) {
      r.expect("grid");
      if(r.count("a class index", g.m_classes) != c)
        r.fail("grid " + std::to_string(c) + " is not where expected");
      for(double& v : g.m_grids[c])
        if(!((v = r.real("a grid value")) >= 0))
          r.fail("a grid value is negative");
    }
    r.expect("end");
    *this = std::move(g);
  }

private:
  // Cells per side: an even number covering [-extent, extent].
  static std::size_t cells(const Context_grid_options& o)
  {
    return 2 * std::size_t(std::ceil(o.extent / o.cell_size - 1e-9));
  }

  // Adds `weight` at (a, b), spread over the cells by a Gaussian of deviation `smoothing` cut at
  // 3 deviations (less its value there, so that the spread is continuous in (a, b)), normalized
  // over its whole support: what falls outside the grid is lost, not moved inside.
  void splat(std::vector<double>& grid, double a, double b, double weight) const
  {
    const double s = m_options.cell_size, half = 0.5 * double(m_n);
    const double ga = a / s + half, gb = b / s + half; // in cells from the grid's corner
    const auto inside = [&](std::int64_t i, std::int64_t j) {
      return i >= 0 && j >= 0 && i < std::int64_t(m_n) && j < std::int64_t(m_n);
    };
    const std::int64_t ci = std::int64_t(std::floor(gb)), cj = std::int64_t(std::floor(ga));
    const double sigma = m_options.smoothing / s, floor_value = std::exp(-4.5);
    // No cell centre within 3 deviations: the object counts in its cell.
    if(std::hypot(double(ci) + 0.5 - gb, double(cj) + 0.5 - ga) >= 3 * sigma) {
      if(inside(ci, cj))
        grid[std::size_t(ci) * m_n + std::size_t(cj)] += weight;
      return;
    }
    const std::int64_t w = std::int64_t(std::ceil(3 * sigma)) + 1;
    double total = 0;
    std::vector<std::pair<std::size_t, double>> cells;
    for(std::int64_t i = ci - w; i <= ci + w; ++i)
      for(std::int64_t j = cj - w; j <= cj + w; ++j) {
        const double di = double(i) + 0.5 - gb, dj = double(j) + 0.5 - ga;
        const double k = (std::max)(0.0, std::exp(-(di * di + dj * dj) / (2 * sigma * sigma)) - floor_value);
        total += k;
        if(k > 0 && inside(i, j))
          cells.emplace_back(std::size_t(i) * m_n + std::size_t(j), k);
      }
    for(const std::pair<std::size_t, double>& c : cells)
      grid[c.first] += weight * c.second / total;
  }

  // The grid's value at (a, b), bilinear between cell centres, 0 outside.
  double interpolate(const std::vector<double>& grid, double a, double b) const
  {
    const double s = m_options.cell_size, half = 0.5 * double(m_n);
    const double ga = a / s + half - 0.5, gb = b / s + half - 0.5;
    if(!(ga > -1) || !(gb > -1) || !(ga < double(m_n)) || !(gb < double(m_n)))
      return 0;
    const std::int64_t i = std::int64_t(std::floor(gb)), j = std::int64_t(std::floor(ga));
    const double ti = gb - double(i), tj = ga - double(j);
    const auto at = [&](std::int64_t p, std::int64_t q) {
      return p < 0 || q < 0 || p >= std::int64_t(m_n) || q >= std::int64_t(m_n) ? 0.0
                                                                                 : grid[std::size_t(p) * m_n + std::size_t(q)];
    };
    return (1 - ti) * ((1 - tj) * at(i, j) + tj * at(i, j + 1)) + ti * ((1 - tj) * at(i + 1, j) + tj * at(i + 1, j + 1));
  }

  // The horizontal positions and labels of `objects`, checked; with `strict`, a label not below
  // `classes` throws, else the object is left out.
  template <typename LabelledRange>
  static void gather(const LabelledRange& objects, std::vector<std::array<double, 2>>& xy,
                     std::vector<std::size_t>& labels, std::size_t classes, bool strict, const std::string& who)
  {
    std::size_t k = 0;
    for(const auto& o : objects) {
      const double x = double(o.position[0]), y = double(o.position[1]);
      if(!std::isfinite(x) || !std::isfinite(y))
        throw Bad_input(who + ": the position of object " + std::to_string(k) + " is not finite");
      const std::size_t l = std::size_t(o.label);
      if(l >= classes && strict)
        throw Bad_input(who + ": label " + std::to_string(l) + " of object " + std::to_string(k) +
                        " is not below the number of classes " + std::to_string(classes));
      if(l < classes) {
        xy.push_back({{x, y}});
        labels.push_back(l);
      }
      ++k;
    }
  }

  Context_grid_options m_options;
  std::size_t m_classes = 0, m_n = 0;
  bool m_streets = false;
  std::vector<std::size_t> m_objects;       // per class, the objects learned from
  std::vector<std::vector<double>> m_grids; // per class, m_n x m_n, row = across, column = along
};

/*!
\ingroup PkgPointSetObjectRecognitionRef
Context features of a set of locations (`context_features()`): one row per location, one column
per feature, to append to the columns of `extract_object_features()`.
*/
struct Context_features
{
  /// the names of the columns: `context.street_distance` when a street map is given, then
  /// `context.prediction.0`, `context.prediction.1`, ... (one per class) when grids are given
  std::vector<std::string> names;
  std::vector<std::vector<double>> values; ///< per location, its features in the order of `names`
};

/*!
\ingroup PkgPointSetObjectRecognitionRef

The context features of candidate locations (thesis section 4.3.4): the distance to the nearest
street when `map` has streets (none without a map), then, when `grids` are trained, the
prediction of each class by the labelled objects (`Context_grids::prediction()`).

Two stages, as in the thesis: train a first classifier without context; train the second with
these features appended, the labelled objects being the true objects of the training scan; to
classify a scan, classify its candidates with the first classifier, then compute these features
with its output as the labelled objects (background labels are ignored) and classify with the
second.

\tparam LabelledRange as for `Context_grids::learn()`, for example `std::vector<Labelled_location>`
\param locations the candidates, \f$ (x, y, z) \f$ in the coordinates of the scan
\param map the streets of the scan, or an empty map
\param grids learned grids, or untrained grids for the street distance only
\param labelled the labelled objects around the candidates (unused when `grids` are untrained)
\returns the names and values of the features, one row per location
\throws CGAL::Shape_analysis::Bad_input when a location is not finite, or as
        `Context_grids::prediction()` (a map given to grids learned without one, or the reverse)
*/
template <typename LabelledRange>
Context_features context_features(const std::vector<std::array<double, 3>>& locations, const Street_map& map,
                                  const Context_grids& grids, const LabelledRange& labelled)
{
  Context_features out;
  out.values.assign(locations.size(), std::vector<double>());
  for(std::size_t i = 0; i < locations.size(); ++i)
    for(double v : locations[i])
      if(!std::isfinite(v))
        throw Bad_input("context_features: location " + std::to_string(i) + " is not finite");
  std::vector<std::vector<double>> predicted;
  if(grids.is_trained())
    predicted = grids.prediction(locations, labelled, map);
  if(!map.empty()) {
    out.names.push_back("context.street_distance");
    for(std::size_t i = 0; i < locations.size(); ++i)
      out.values[i].push_back(map.distance(locations[i][0], locations[i][1]));
  }
  for(std::size_t c = 0; c < grids.number_of_classes(); ++c)
    out.names.push_back("context.prediction." + std::to_string(c));
  for(std::size_t i = 0; i < predicted.size(); ++i)
    out.values[i].insert(out.values[i].end(), predicted[i].begin(), predicted[i].end());
  return out;
}

} // namespace Point_set_object_recognition
} // namespace CGAL

#endif // CGAL_POINT_SET_OBJECT_RECOGNITION_OBJECT_CONTEXT_H
