// SPDX-FileCopyrightText: Copyright (c) 2026 the VTK Ice developers
// SPDX-License-Identifier: BSD-3-Clause
// ice-render's preset files: "NAME = VALUE" lines of the settings in vtkIceLookTable.h.
#include "vtkIceLookTable.h"

#include <algorithm>
#include <fstream>

namespace vtkIceLookTable
{
namespace
{
std::string Trim(const std::string& text)
{
  const auto begin = text.find_first_not_of(" \t\r");
  const auto end = text.find_last_not_of(" \t\r");
  return begin == std::string::npos ? std::string() : text.substr(begin, end - begin + 1);
}
}

//------------------------------------------------------------------------------
std::string ReadPreset(const std::string& path, Assignments& assignments)
{
  std::ifstream file(path);
  if (!file)
  {
    return "cannot read preset '" + path + "'";
  }
  std::string line;
  for (int number = 1; std::getline(file, line); ++number)
  {
    line = Trim(line.substr(0, line.find('#')));
    if (line.empty())
    {
      continue;
    }
    const auto equals = line.find('=');
    const std::string where = path + ":" + std::to_string(number) + ": ";
    if (equals == std::string::npos)
    {
      return where + "expected NAME = VALUE";
    }
    const std::string name = Trim(line.substr(0, equals));
    const std::string value = Trim(line.substr(equals + 1));
    if (!Find(name))
    {
      return where + "unknown setting '" + name + "'";
    }
    const std::string problem = Check({ { name, value } });
    if (!problem.empty())
    {
      return where + problem;
    }
    assignments.emplace_back(name, value);
  }
  return file.bad() ? "cannot read preset '" + path + "'" : std::string();
}

//------------------------------------------------------------------------------
std::string WritePreset(const Target& target, const std::vector<std::string>& cameraGiven)
{
  std::string text = "# VTK Ice look (ice-render --print-preset); use with --preset FILE\n";
  for (const Setting& setting : Settings())
  {
    const std::string name = setting.Name;
    if ((setting.Camera &&
          std::find(cameraGiven.begin(), cameraGiven.end(), name) == cameraGiven.end()) ||
      setting.SynonymOf)
    {
      continue;
    }
    const std::string value = Value(target, name);
    if (!value.empty()) // a setting of an object the target lacks (its tone mapping)
    {
      text += name + " = " + value + "\n";
    }
  }
  return text;
}
}
