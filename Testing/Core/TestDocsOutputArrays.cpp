// SPDX-License-Identifier: BSD-3-Clause
// The user guide's table of point arrays (docs/user-guide.md, section Output)
// is the one list of the arrays Output Arrays leaves off by default: it must
// name every array of bp::outputArrays() and no other, each with its
// components and on or off as the table in Core says.
#include "OutputArrays.h"

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace
{
struct DocRow
{
  std::string type;    ///< "float", "3 floats", "id", "int"
  std::string initial; ///< "on" or "off"
};

std::string trim(const std::string& s)
{
  const auto first = s.find_first_not_of(' ');
  const auto last = s.find_last_not_of(' ');
  return first == std::string::npos ? std::string() : s.substr(first, last - first + 1);
}

/// The cells of a Markdown table row, "| a | b |" -> {"a", "b"}; a "\|"
/// inside a cell stays in it.
std::vector<std::string> cells(const std::string& line)
{
  std::vector<std::string> out;
  std::string cell;
  for (std::size_t i = 1; i < line.size(); ++i)
  {
    if (line[i] == '\\' && i + 1 < line.size() && line[i + 1] == '|')
    {
      cell += "\\|";
      ++i;
    }
    else if (line[i] == '|')
    {
      out.push_back(trim(cell));
      cell.clear();
    }
    else
    {
      cell += line[i];
    }
  }
  return out;
}

/// The rows of the table headed "| point array | type | by default | meaning |",
/// by array name (the backticks taken off). Fails the test on a malformed row.
std::map<std::string, DocRow> documentedArrays(const std::string& path)
{
  std::ifstream in(path);
  EXPECT_TRUE(in.good()) << "cannot read " << path;
  std::map<std::string, DocRow> rows;
  std::string line;
  bool inTable = false;
  while (std::getline(in, line))
  {
    if (!inTable)
    {
      const std::vector<std::string> head =
        line.rfind("|", 0) == 0 ? cells(line) : std::vector<std::string>();
      inTable = head.size() == 4 && head[0] == "point array" && head[1] == "type" &&
        head[2] == "by default" && head[3] == "meaning";
      if (inTable)
      {
        std::getline(in, line); // |---|---|---|---|
      }
      continue;
    }
    if (line.rfind("|", 0) != 0)
    {
      break;
    }
    const std::vector<std::string> row = cells(line);
    EXPECT_EQ(row.size(), 4u) << line;
    if (row.size() != 4)
    {
      continue;
    }
    const std::string& quoted = row[0];
    EXPECT_TRUE(quoted.size() > 2 && quoted.front() == '`' && quoted.back() == '`') << line;
    const std::string name = quoted.substr(1, quoted.size() - 2);
    EXPECT_EQ(rows.count(name), 0u) << name << " is listed twice";
    rows[name] = { row[1], row[2] };
  }
  EXPECT_TRUE(inTable) << "no table headed '| point array | type | by default | meaning |' in "
                       << path;
  return rows;
}

/// The components the guide's type names: "float", "id", "int" 1; "N floats" N.
int componentsOf(const std::string& type)
{
  if (type == "float" || type == "id" || type == "int")
  {
    return 1;
  }
  std::istringstream in(type);
  int n = 0;
  std::string word;
  return (in >> n >> word) && word == "floats" ? n : 0;
}
} // namespace

TEST(DocsOutputArrays, TheUserGuidesTableIsCoresTable)
{
  const std::string path = std::string(BP_DOCS_DIR) + "/user-guide.md";
  const std::map<std::string, DocRow> documented = documentedArrays(path);
  int off = 0;
  for (const bp::OutputArray& a : bp::outputArrays())
  {
    const auto it = documented.find(a.name);
    if (it == documented.end())
    {
      ADD_FAILURE() << a.name << " is an output array the user guide's table leaves out";
      continue;
    }
    EXPECT_EQ(it->second.initial, a.onByDefault ? "on" : "off")
      << a.name << ": the user guide's 'by default' column against OutputArrays.cpp";
    EXPECT_EQ(componentsOf(it->second.type), a.components) << a.name << ": " << it->second.type;
    off += a.onByDefault ? 0 : 1;
  }
  for (const auto& [name, row] : documented)
  {
    EXPECT_NE(bp::findOutputArray(name), nullptr)
      << name << " is in the user guide's table but not an output array";
  }
  // The check compares something: Core has arrays off by default.
  EXPECT_GT(off, 0);
}
