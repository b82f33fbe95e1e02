// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_TOKEN_READER_H
#define CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_TOKEN_READER_H

// Strict reading of the whitespace-separated tokens of the package's versioned text files
// (classifier models, context grids): every failure throws Bad_input, prefixed with the kind of
// file.

#include <CGAL/Shape_analysis/Bad_input.h>

#include <cmath>
#include <cstdlib>
#include <istream>
#include <string>
#include <utility>

namespace CGAL {
namespace Point_set_object_recognition {
namespace internal {

class Token_reader
{
public:
  Token_reader(std::istream& is, std::string file) : m_is(is), m_file(std::move(file)) {}

  [[noreturn]] void fail(const std::string& what) const { fail_as(m_file, what); }
  [[noreturn]] static void fail_as(const std::string& file, const std::string& what)
  {
    throw CGAL::Shape_analysis::Bad_input(file + ": " + what);
  }

  // Reads the first line, which must be `<magic> 1` (`what`: what such a file holds).
  void first_line(const std::string& magic, const std::string& what)
  {
    std::string line;
    if(!std::getline(m_is, line))
      fail("empty, expected the line '" + magic + " 1'");
    if(!line.empty() && line.back() == '\r')
      line.pop_back();
    if(line.compare(0, magic.size() + 1, magic + " ") != 0)
      fail("the first line is not '" + magic + " 1', this is not " + what);
    if(line != magic + " 1")
      fail("unsupported format version '" + line.substr(magic.size() + 1) + "' (this library reads version 1)");
  }

  std::string token(const std::string& what)
  {
    std::string t;
    if(!(m_is >> t))
      fail("truncated, " + what + " is missing");
    return t;
  }

  void expect(const std::string& word)
  {
    const std::string t = token("'" + word + "'");
    if(t != word)
      fail("expected '" + word + "', read '" + t + "'");
  }

  double real(const std::string& what)
  {
    const std::string t = token(what);
    char* end = nullptr;
    const double x = std::strtod(t.c_str(), &end);
    if(end == t.c_str() || *end != '\0' || !std::isfinite(x))
      fail(what + " '" + t + "' is not a finite number");
    return x;
  }

  std::size_t count(const std::string& what, std::size_t at_most)
  {
    const std::string t = token(what);
    if(t.empty() || t.size() > 18 || t.find_first_not_of("0123456789") != std::string::npos)
      fail(what + " '" + t + "' is not a non-negative integer");
    const std::size_t n = std::size_t(std::strtoull(t.c_str(), nullptr, 10));
    if(n > at_most)
      fail(what + " " + t + " is over " + std::to_string(at_most));
    return n;
  }

private:
  std::istream& m_is;
  std::string m_file;
};

} // namespace internal
} // namespace Point_set_object_recognition
} // namespace CGAL

#endif // CGAL_POINT_SET_OBJECT_RECOGNITION_INTERNAL_TOKEN_READER_H
