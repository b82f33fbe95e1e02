// Copyright (c) 2026 CGAL Global Shape Analysis contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SHAPE_ANALYSIS_INTERNAL_JSON_H
#define CGAL_SHAPE_ANALYSIS_INTERNAL_JSON_H

// A small JSON value for the reports of the command-line tool and the benchmark programs.

#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Shape_analysis {
namespace internal {

class Json
{
public:
  enum Kind { NUL, BOOLEAN, NUMBER, STRING, ARRAY, OBJECT };

  Json() = default;
  Json(std::nullptr_t) {}
  Json(bool b) : m_kind(BOOLEAN), m_bool(b) {}
  Json(double d) : m_kind(NUMBER), m_number(d) {}
  Json(int i) : m_kind(NUMBER), m_number(i), m_integer(true) {}
  Json(long i) : m_kind(NUMBER), m_number(double(i)), m_integer(true) {}
  Json(long long i) : m_kind(NUMBER), m_number(double(i)), m_integer(true) {}
  Json(unsigned int i) : m_kind(NUMBER), m_number(i), m_integer(true) {}
  Json(unsigned long i) : m_kind(NUMBER), m_number(double(i)), m_integer(true) {}
  Json(unsigned long long i) : m_kind(NUMBER), m_number(double(i)), m_integer(true) {}
  Json(const char* s) : m_kind(STRING), m_string(s) {}
  Json(std::string s) : m_kind(STRING), m_string(std::move(s)) {}
  template <typename T>
  Json(const std::vector<T>& values) : m_kind(ARRAY)
  {
    for(const T& v : values)
      m_array.emplace_back(v);
  }

  static Json array() { Json j; j.m_kind = ARRAY; return j; }
  static Json object() { Json j; j.m_kind = OBJECT; return j; }

  Kind kind() const { return m_kind; }

  // Object member (created on first use; keeps insertion order).
  Json& operator[](const std::string& key)
  {
    if(m_kind != OBJECT) {
      m_kind = OBJECT;
      m_members.clear();
    }
    for(auto& m : m_members)
      if(m.first == key)
        return m.second;
    m_members.emplace_back(key, Json());
    return m_members.back().second;
  }

  void push_back(Json v)
  {
    if(m_kind != ARRAY) {
      m_kind = ARRAY;
      m_array.clear();
    }
    m_array.push_back(std::move(v));
  }

  std::string dump(int indent = 2) const
  {
    std::ostringstream out;
    write(out, indent, 0);
    return out.str();
  }

private:
  static void write_string(std::ostream& out, const std::string& s)
  {
    out << '"';
    for(unsigned char c : s) {
      switch(c) {
      case '"': out << "\\\""; break;
      case '\\': out << "\\\\"; break;
      case '\n': out << "\\n"; break;
      case '\r': out << "\\r"; break;
      case '\t': out << "\\t"; break;
      default:
        if(c < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof(buf), "\\u%04x", c);
          out << buf;
        } else
          out << c;
      }
    }
    out << '"';
  }

  void write(std::ostream& out, int indent, int depth) const
  {
    const std::string pad = indent > 0 ? std::string(std::size_t(indent * (depth + 1)), ' ') : "";
    const std::string end_pad = indent > 0 ? std::string(std::size_t(indent * depth), ' ') : "";
    const char* nl = indent > 0 ? "\n" : "";
    switch(m_kind) {
    case NUL: out << "null"; break;
    case BOOLEAN: out << (m_bool ? "true" : "false"); break;
    case NUMBER:
      if(!std::isfinite(m_number))
        out << "null";
      else if(m_integer || (std::floor(m_number) == m_number && std::abs(m_number) < 1e15))
        out << static_cast<long long>(m_number);
      else {
        char buf[32];
        std::snprintf(buf, sizeof(buf), "%.10g", m_number);
        out << buf;
      }
      break;
    case STRING: write_string(out, m_string); break;
    case ARRAY: {
      if(m_array.empty()) {
        out << "[]";
        break;
      }
      bool scalars = true;
      for(const Json& v : m_array)
        scalars = scalars && v.m_kind != ARRAY && v.m_kind != OBJECT;
      if(scalars) { // short arrays of numbers on one line
        out << '[';
        for(std::size_t i = 0; i < m_array.size(); ++i) {
          if(i)
            out << ", ";
          m_array[i].write(out, 0, 0);
        }
        out << ']';
        break;
      }
      out << '[' << nl;
      for(std::size_t i = 0; i < m_array.size(); ++i) {
        out << pad;
        m_array[i].write(out, indent, depth + 1);
        out << (i + 1 < m_array.size() ? "," : "") << nl;
      }
      out << end_pad << ']';
      break;
    }
    case OBJECT: {
      if(m_members.empty()) {
        out << "{}";
        break;
      }
      out << '{' << nl;
      for(std::size_t i = 0; i < m_members.size(); ++i) {
        out << pad;
        write_string(out, m_members[i].first);
        out << (indent > 0 ? ": " : ":");
        m_members[i].second.write(out, indent, depth + 1);
        out << (i + 1 < m_members.size() ? "," : "") << nl;
      }
      out << end_pad << '}';
      break;
    }
    }
  }

  Kind m_kind = NUL;
  bool m_bool = false;
  double m_number = 0;
  bool m_integer = false;
  std::string m_string;
  std::vector<Json> m_array;
  std::vector<std::pair<std::string, Json>> m_members;
};

} // namespace internal
} // namespace Shape_analysis
} // namespace CGAL

#endif // CGAL_SHAPE_ANALYSIS_INTERNAL_JSON_H
