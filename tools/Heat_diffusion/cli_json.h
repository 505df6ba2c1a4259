// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The JSON summaries the subcommands print with --json.

#ifndef CGAL_HEAT_DIFFUSION_TOOLS_CLI_JSON_H
#define CGAL_HEAT_DIFFUSION_TOOLS_CLI_JSON_H

#include <cmath>
#include <cstdio>
#include <iomanip>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace heat_diffusion_cli {

// A JSON object written member by member; values are numbers, strings or nested
// objects given as already formatted JSON.
class Json_object
{
public:
  Json_object& number(const std::string& key, double value)
  {
    std::ostringstream os;
    if(std::isfinite(value))
      os << std::setprecision(17) << value;
    else
      os << "null";  // JSON has no NaN or infinity
    return raw(key, os.str());
  }
  Json_object& integer(const std::string& key, long long value) { return raw(key, std::to_string(value)); }
  Json_object& boolean(const std::string& key, bool value) { return raw(key, value ? "true" : "false"); }
  Json_object& string(const std::string& key, const std::string& value) { return raw(key, quote(value)); }
  Json_object& object(const std::string& key, const Json_object& value) { return raw(key, value.str()); }
  Json_object& raw(const std::string& key, const std::string& json)
  {
    members_.emplace_back(key, json);
    return *this;
  }
  std::string str() const
  {
    std::string s = "{";
    for(std::size_t i = 0; i < members_.size(); ++i)
      s += (i ? ", " : "") + quote(members_[i].first) + ": " + members_[i].second;
    return s + "}";
  }
  static std::string quote(const std::string& s)
  {
    std::string q = "\"";
    for(char c : s)
    {
      if(c == '"' || c == '\\')
        q += std::string("\\") + c;
      else if(static_cast<unsigned char>(c) < 0x20)
      {
        char buffer[8];
        std::snprintf(buffer, sizeof buffer, "\\u%04x", c);
        q += buffer;
      }
      else
        q += c;
    }
    return q + "\"";
  }

private:
  std::vector<std::pair<std::string, std::string> > members_;
};

// A list of numbers as a JSON array, each with 17 significant digits (exact doubles).
inline std::string number_list_json(const std::vector<double>& values)
{
  std::string list = "[";
  for(std::size_t j = 0; j < values.size(); ++j)
  {
    std::ostringstream os;
    os << std::setprecision(17) << values[j];
    list += (j ? ", " : "") + os.str();
  }
  return list + "]";
}

} // namespace heat_diffusion_cli

#endif // CGAL_HEAT_DIFFUSION_TOOLS_CLI_JSON_H
