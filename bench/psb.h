// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHAPE_ANALYSIS_BENCH_PSB_H
#define CGAL_SHAPE_ANALYSIS_BENCH_PSB_H

// Reading the Princeton Segmentation Benchmark subset in ../shared/data/psb and scoring
// segmentations against its human segmentations (Rand Index error, as the benchmark defines it).

#include <Shape_analysis_support/Partition_agreement.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>
namespace SAS = CGAL::Shape_analysis_support;

namespace psb {

struct Mesh_entry
{
  int id = 0;
  std::string mesh_class;
  std::filesystem::path off;
  std::vector<std::vector<std::size_t>> human; // one labeling per person
};

inline std::string class_of(int id)
{
  static const char* names[] = {"Human",  "Cup",      "Glasses", "Airplane", "Ant",
                                "Chair",  "Octopus",  "Table",   "Teddy",    "Hand",
                                "Plier",  "Fish",     "Bird",    "Spring",   "Armadillo",
                                "Bust",   "Mech",     "Bearing", "Vase",     "Fourleg"};
  const int k = (id - 1) / 20;
  return (k >= 0 && k < 20) ? names[k] : "Unknown";
}

inline bool read_labels(const std::filesystem::path& file, std::vector<std::size_t>& labels)
{
  std::ifstream in(file);
  if(!in)
    return false;
  labels.clear();
  long long v;
  while(in >> v)
    labels.push_back(static_cast<std::size_t>(v < 0 ? 0 : v));
  return true;
}

// All meshes of the subset that have an OFF file and at least one segmentation, by id.
inline std::vector<Mesh_entry> list_meshes(const std::filesystem::path& root)
{
  namespace fs = std::filesystem;
  std::vector<Mesh_entry> result;
  if(!fs::is_directory(root / "off"))
    return result;
  for(const auto& entry : fs::directory_iterator(root / "off")) {
    if(entry.path().extension() != ".off")
      continue;
    Mesh_entry m;
    try {
      m.id = std::stoi(entry.path().stem().string());
    } catch(...) {
      continue;
    }
    m.off = entry.path();
    m.mesh_class = class_of(m.id);
    const fs::path seg_dir = root / "seg" / std::to_string(m.id);
    if(!fs::is_directory(seg_dir))
      continue;
    std::vector<fs::path> files;
    for(const auto& s : fs::directory_iterator(seg_dir))
      if(s.path().extension() == ".seg")
        files.push_back(s.path());
    std::sort(files.begin(), files.end());
    for(const auto& f : files) {
      std::vector<std::size_t> labels;
      if(read_labels(f, labels))
        m.human.push_back(std::move(labels));
    }
    if(!m.human.empty())
      result.push_back(std::move(m));
  }
  std::sort(result.begin(), result.end(),
            [](const Mesh_entry& a, const Mesh_entry& b) { return a.id < b.id; });
  return result;
}

inline std::size_t number_of_labels(const std::vector<std::size_t>& labels)
{
  std::vector<std::size_t> sorted(labels);
  std::sort(sorted.begin(), sorted.end());
  return static_cast<std::size_t>(std::unique(sorted.begin(), sorted.end()) - sorted.begin());
}

// The most frequent segment count among the human segmentations (the smallest on a tie).
inline std::size_t mode_segment_count(const Mesh_entry& m)
{
  std::map<std::size_t, int> counts;
  for(const auto& h : m.human)
    ++counts[number_of_labels(h)];
  std::size_t best = 0;
  int best_count = -1;
  for(const auto& c : counts)
    if(c.second > best_count) {
      best = c.first;
      best_count = c.second;
    }
  return best;
}

// 1 - Rand Index between two labelings of the same faces (face pairs, unweighted).
inline double rand_index_error(const std::vector<std::size_t>& a, const std::vector<std::size_t>& b)
{
  if(a.size() != b.size() || a.size() < 2)
    return 1.0;
  return 1.0 - SAS::rand_index(a, b);
}

// Mean Rand Index error of `labels` against every human segmentation of the mesh.
inline double mean_rand_index_error(const Mesh_entry& m, const std::vector<std::size_t>& labels)
{
  double sum = 0;
  std::size_t count = 0;
  for(const auto& h : m.human)
    if(h.size() == labels.size()) {
      sum += rand_index_error(h, labels);
      ++count;
    }
  return count > 0 ? sum / double(count) : 1.0;
}

} // namespace psb

#endif // CGAL_SHAPE_ANALYSIS_BENCH_PSB_H
